# kappa_render: the OpenGL 3.3 core line-drawing renderer (render/*/*.cpp).
# Included from the top CMakeLists.txt when render/ has sources.
#   - glad 2 is generated at build time (python3-glad, offline with --reproducible)
#   - shaders/*/*.glsl are embedded into the library as string literals, so the
#     kappa executable runs from any directory
#   - EGL for headless contexts, libpng for PNG output, libstb (stb_image_write) for JPEG,
#     cairo for PDF output

find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(PNG REQUIRED)
find_program(KAPPA_GLAD_EXECUTABLE glad REQUIRED)

# --- glad: GL core loader (3.3 is what the renderer needs; 4.3 adds the compute line path) ------------------------------------------------
set(KAPPA_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${KAPPA_GLAD_DIR}/src/gl.c ${KAPPA_GLAD_DIR}/include/glad/gl.h
  COMMAND ${KAPPA_GLAD_EXECUTABLE} --reproducible --quiet --api gl:core=4.6 --out-path ${KAPPA_GLAD_DIR} c
  COMMENT "Generating the glad OpenGL 4.6 core loader"
  VERBATIM)
add_library(kappa_glad STATIC ${KAPPA_GLAD_DIR}/src/gl.c)
target_include_directories(kappa_glad PUBLIC ${KAPPA_GLAD_DIR}/include)
set_target_properties(kappa_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)

# --- shaders embedded as string literals --------------------------------------
include(${CMAKE_SOURCE_DIR}/cmake/embedded_shaders.cmake)
kappa_embed_shaders(${CMAKE_SOURCE_DIR} KAPPA_SHADER_CPP)

# --- the library ----------------------------------------------------------------
add_library(kappa_render STATIC ${KAPPA_RENDER_SOURCES} ${KAPPA_SHADER_CPP})
target_include_directories(kappa_render PUBLIC ${CMAKE_SOURCE_DIR})
target_link_libraries(kappa_render PUBLIC kappa_geometry kappa_glad OpenGL::OpenGL OpenGL::EGL
                      PRIVATE PNG::PNG stb)
# Position-independent: the Python module (python/) links it into a shared object.
set_target_properties(kappa_render PROPERTIES POSITION_INDEPENDENT_CODE ON)
# The per-frame CPU line pass (extraction, merging, raster) at -O3 like the
# geometry library: the same floating-point semantics, bit-identical output.
target_compile_options(kappa_render PRIVATE $<$<CONFIG:Release>:-O3 -fno-semantic-interposition>)

# --- the viewer's window and UI: GLFW (X11) and Dear ImGui ----------------------
# Debian's libimgui.a already contains the GLFW and OpenGL3 backends (platform.md).
find_package(PkgConfig REQUIRED)
pkg_check_modules(KAPPA_UI REQUIRED IMPORTED_TARGET glfw3 imgui)
target_link_libraries(kappa_render PUBLIC PkgConfig::KAPPA_UI)
pkg_check_modules(KAPPA_CAIRO REQUIRED IMPORTED_TARGET cairo cairo-pdf)
target_link_libraries(kappa_render PRIVATE PkgConfig::KAPPA_CAIRO)
