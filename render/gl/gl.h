// The one header through which render/ sees OpenGL: the glad 2 loader
// generated at build time for GL 4.6 core (cmake/render.cmake). The
// renderer needs 3.3; entry points the context lacks stay null, and
// GLAD_GL_VERSION_4_3 says whether the compute path can run.
#pragma once

#include <glad/gl.h>
