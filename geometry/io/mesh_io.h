// Mesh input and output: the one header to include.
//
//   Mesh m = load_mesh("bunny.ply");          // .ply .obj .off .stl .gltf .glb
//   write_csv("out.csv", m, fields);          // conventions.md columns
//   write_ply("out.ply", m, fields);          // same values as properties
//
// Every reader fails with MeshLoadError, every writer with MeshWriteError;
// what() is one line "PATH: problem".
#pragma once

#include "csv_io.h"
#include "gltf_io.h"
#include "io_errors.h"
#include "obj_io.h"
#include "off_io.h"
#include "ply_io.h"
#include "stl_io.h"

#include <string>

namespace kappa {

enum class MeshFormat { Unknown, Ply, Obj, Off, Stl, Gltf };

// Format named by a path's extension (case-insensitive), or Unknown.
MeshFormat format_from_extension(const std::string& path);
// Format recognised from the first bytes (PLY magic, OFF keyword, binary STL
// size, "solid", glTF's binary magic or JSON "asset", OBJ statements), or Unknown.
MeshFormat format_from_content(const char* data, size_t size);

// Reads a mesh from memory in the given format (Unknown: sniff the content).
Mesh read_mesh(const char* data, size_t size, MeshFormat format, const std::string& name);

// Loads a mesh file: the format comes from the extension, or from the content
// when the extension is missing or unknown. Throws MeshLoadError.
Mesh load_mesh(const std::string& path);

}  // namespace kappa
