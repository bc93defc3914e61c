#pragma once
// The one way runtime code reaches OpenGL: the glad 4.5 core loader.
#include <glad/gl.h>
