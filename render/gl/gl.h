// The one header through which render/ sees OpenGL: the glad 2 loader
// generated at build time for GL 3.3 core (cmake/render.cmake).
#pragma once

#include <glad/gl.h>
