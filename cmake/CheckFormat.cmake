# cmake -DSOURCE_DIR=... -DCLANG_FORMAT=... -P cmake/CheckFormat.cmake
# Fails, naming each file, when a C++ source of the project differs from what
# clang-format makes of it with the project's .clang-format. The fuzz corpus
# and the build trees are not sources.
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/core/*.cpp ${SOURCE_DIR}/core/*.h
     ${SOURCE_DIR}/preprocess/*.cpp ${SOURCE_DIR}/preprocess/*.h
     ${SOURCE_DIR}/reference/*.cpp ${SOURCE_DIR}/reference/*.h
     ${SOURCE_DIR}/runtime/*.cpp ${SOURCE_DIR}/runtime/*.h
     ${SOURCE_DIR}/hybrid/*.cpp ${SOURCE_DIR}/hybrid/*.h
     ${SOURCE_DIR}/methods/*.cpp ${SOURCE_DIR}/methods/*.h
     ${SOURCE_DIR}/viewer/*.cpp ${SOURCE_DIR}/viewer/*.h
     ${SOURCE_DIR}/apps/*.cpp ${SOURCE_DIR}/apps/*.h
     ${SOURCE_DIR}/bench/*.cpp ${SOURCE_DIR}/bench/*.h
     ${SOURCE_DIR}/python/*.cpp ${SOURCE_DIR}/python/*.h
     ${SOURCE_DIR}/examples/*.cpp ${SOURCE_DIR}/examples/*.h
     ${SOURCE_DIR}/fuzz/*.cpp ${SOURCE_DIR}/fuzz/*.h
     ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.h)
list(LENGTH sources count)
if(count LESS 100)
  message(FATAL_ERROR "found only ${count} sources under ${SOURCE_DIR}: is SOURCE_DIR right?")
endif()
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror --style=file ${sources}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  string(REGEX MATCHALL "[^\n:]+:[0-9]+:[0-9]+: (warning|error): code should be clang-formatted" lines "${errors}")
  set(offending "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: .*" "" file "${line}")
    list(APPEND offending "${file}")
  endforeach()
  list(REMOVE_DUPLICATES offending)
  string(REPLACE ";" "\n" offending "${offending}")
  message(FATAL_ERROR "not formatted as .clang-format says (run clang-format -i on them):\n${offending}")
endif()
message(STATUS "${count} sources formatted as .clang-format says")
