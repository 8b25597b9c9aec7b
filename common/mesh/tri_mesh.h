// A plain VCG triangle mesh in double precision, for the tests, benchmarks and any user of
// the library outside MeshLab (inside MeshLab the algorithms run on CMeshO).
#pragma once

#include <vcg/complex/complex.h>

namespace hht {

class TriVertex;
class TriFace;
struct TriUsedTypes : public vcg::UsedTypes<vcg::Use<TriVertex>::AsVertexType, vcg::Use<TriFace>::AsFaceType> {};
class TriVertex : public vcg::Vertex<TriUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                     vcg::vertex::Qualityd, vcg::vertex::Color4b, vcg::vertex::VFAdj,
                                     vcg::vertex::BitFlags> {};
class TriFace : public vcg::Face<TriUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                                 vcg::face::FFAdj, vcg::face::VFAdj, vcg::face::BitFlags> {};
class TriMesh : public vcg::tri::TriMesh<std::vector<TriVertex>, std::vector<TriFace>> {};

}  // namespace hht
