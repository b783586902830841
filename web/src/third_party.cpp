// The implementations of the header-only readers and writers Debian ships as
// shared libraries for the desktop build (tinyobjloader, tinygltf, stb_image_write):
// compiled here for the browser build from the same headers.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
