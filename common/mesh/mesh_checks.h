// Input checks shared by the filters, with messages a MeshLab user can act on.
#pragma once

#include "mesh/mesh_arrays.h"

#include <string>

namespace hht {

// Fails on a mesh without faces and on non-finite coordinates.
bool check_triangle_mesh(const Positions& positions, const Faces& faces, std::string& error);

}  // namespace hht
