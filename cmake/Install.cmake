# Install rules and the CMake package, so that a host project can write
#   find_package(Lucent REQUIRED)
#   target_link_libraries(app PRIVATE Lucent::offscreen)   # or Lucent::runtime on its own context
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LUCENT_INSTALL_INCLUDE ${CMAKE_INSTALL_INCLUDEDIR}/lucent)
set_target_properties(lucent_core PROPERTIES EXPORT_NAME core)
set_target_properties(lucent_glad PROPERTIES EXPORT_NAME glad)
set_target_properties(lucent_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(lucent_offscreen PROPERTIES EXPORT_NAME offscreen)
set_target_properties(lucent_preprocess PROPERTIES EXPORT_NAME preprocess)
set_target_properties(lucent_reference PROPERTIES EXPORT_NAME reference)
# The installed lucent finds its libraries beside it, wherever the prefix is.
set_target_properties(lucent PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

install(TARGETS lucent_core lucent_glad lucent_runtime lucent_offscreen lucent_preprocess lucent_reference
        EXPORT LucentTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${LUCENT_INSTALL_INCLUDE})
install(TARGETS lucent RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The OpenVDB plug-ins (core/plugin_library.h): beside the libraries that open them.
install(TARGETS lucent_core_openvdb lucent_preprocess_openvdb LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
if(LUCENT_HAVE_OPENCL)
  # The hybrid (multiple scattering on OpenCL): its solver's header only; OpenCL stays private.
  set_target_properties(lucent_hybrid PROPERTIES EXPORT_NAME hybrid)
  install(TARGETS lucent_hybrid EXPORT LucentTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} INCLUDES DESTINATION ${LUCENT_INSTALL_INCLUDE})
  install(FILES hybrid/multiple_scattering.h DESTINATION ${LUCENT_INSTALL_INCLUDE}/hybrid)
endif()
install(DIRECTORY core/ DESTINATION ${LUCENT_INSTALL_INCLUDE}/core FILES_MATCHING PATTERN "*.h")
install(FILES preprocess/preprocessor.h DESTINATION ${LUCENT_INSTALL_INCLUDE}/preprocess)
install(FILES reference/reference_renderer.h reference/reference_method.h DESTINATION ${LUCENT_INSTALL_INCLUDE}/reference)
# The runtime's public headers only: internal/ holds its private ones.
install(DIRECTORY runtime/ DESTINATION ${LUCENT_INSTALL_INCLUDE}/runtime FILES_MATCHING PATTERN "*.h" PATTERN internal EXCLUDE)
install(EXPORT LucentTargets NAMESPACE Lucent:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lucent)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/LucentConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/LucentConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lucent)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/LucentConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/LucentConfig.cmake ${CMAKE_BINARY_DIR}/LucentConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lucent)
