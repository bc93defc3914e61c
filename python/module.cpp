// The lucent Python module: load a scene (JSON or glTF), edit it, preprocess
// it and render it with any method into a numpy array (docs/python.md).
#include <dlfcn.h>
#include <pybind11/pybind11.h>

#include "core/error.h"
#include "core/scene.h"
#include "preprocess/preprocessor.h"
#include "python/bindings.h"

namespace {

// Lucent's OpenVDB plug-ins (core/plugin_library.h) take Lucent's symbols from
// the process, as the lucent command loads them. Python loads an extension
// module and the libraries it needs with RTLD_LOCAL, where a plug-in cannot
// see them: the libraries that hold function are made global, once.
void makeGlobal(const void* function) {
    Dl_info info{};
    if (dladdr(function, &info) && info.dli_fname) dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL);
}

}  // namespace

PYBIND11_MODULE(lucent, m) {
    makeGlobal(reinterpret_cast<const void*>(&lucent::withoutTransforms));  // liblucent_core
    makeGlobal(reinterpret_cast<const void*>(&lucent::qualityPreset));      // liblucent_preprocess
    m.doc() =
        "Lucent: light scattering inside translucent objects. load_scene, preprocess, render, methods, presets "
        "(docs/python.md).";
    // Every error the command line prints as one line arrives as lucent.Error with that line.
    pybind11::register_exception<lucent::Error>(m, "Error", PyExc_RuntimeError);
    lucent::python::bindSceneTypes(m);
    lucent::python::bindRendering(m);
}
