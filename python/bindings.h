#pragma once
// The pieces of the lucent Python module (python/module.cpp joins them).
#include <pybind11/pybind11.h>

namespace lucent::python {

void bindSceneTypes(pybind11::module_& m);  // Scene, Camera, Light, Object, load_scene
void bindRendering(pybind11::module_& m);   // preprocess, render, methods, presets

}  // namespace lucent::python
