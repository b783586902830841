// tinyobjloader compiled from its header with the fuzzing instrumentation
// (the normal build links Debian's prebuilt libtinyobjloader instead).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
