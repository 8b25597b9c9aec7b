#include "reconstruction/flip_guard.h"

#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

namespace {

Eigen::RowVector3d area_vector(const Positions& p, const Faces& faces, Eigen::Index f) {
  const Eigen::RowVector3d a = p.row(faces(f, 0));
  return (p.row(faces(f, 1)) - a).cross(p.row(faces(f, 2)) - a);
}

// The sum of a face's corners' vertex normals: the surface around it.
Eigen::RowVector3d corners(const Positions& normals, const Faces& faces, Eigen::Index f) {
  return normals.row(faces(f, 0)) + normals.row(faces(f, 1)) + normals.row(faces(f, 2));
}

// The faces of each vertex, in compressed rows.
struct VertexFaces {
  std::vector<int> offsets, faces;
  const int* begin(int v) const { return faces.data() + offsets[v]; }
  const int* end(int v) const { return faces.data() + offsets[v + 1]; }
};

VertexFaces vertex_faces(const Faces& faces, Eigen::Index vertex_count) {
  VertexFaces out;
  out.offsets.assign(vertex_count + 1, 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++out.offsets[faces(f, k) + 1];
  for (Eigen::Index v = 0; v < vertex_count; ++v) out.offsets[v + 1] += out.offsets[v];
  out.faces.resize(out.offsets.back());
  std::vector<int> next(out.offsets.begin(), out.offsets.end() - 1);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) out.faces[next[faces(f, k)]++] = static_cast<int>(f);
  return out;
}

}  // namespace

int restore_turned_faces(const Positions& input, const Faces& faces, Positions& result) {
  std::vector<unsigned char> restored(input.rows(), 0);
  int count = 0;
  // Each pass restores at least one vertex or stops, so this ends; a few passes suffice.
  for (bool changed = true; changed;) {
    changed = false;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d before = area_vector(input, faces, f);
      if (before.squaredNorm() == 0 || before.dot(area_vector(result, faces, f)) >= 0) continue;
      for (int k = 0; k < 3; ++k) {
        const int v = faces(f, k);
        if (restored[v]) continue;
        result.row(v) = input.row(v);
        restored[v] = 1;
        ++count;
        changed = true;
      }
    }
  }
  return count;
}

int restore_turned_faces_that_fit(const Positions& input, const Faces& faces, double max_degrees, Positions& result) {
  const Positions input_normals = area_weighted_vertex_normals(input, faces);
  const Positions surface = area_weighted_vertex_normals(result, faces);  // kept as it was before any restore
  const VertexFaces faces_of = vertex_faces(faces, input.rows());
  const double min_cosine = std::cos(max_degrees * M_PI / 180);
  auto fits = [&](Eigen::Index f, const Positions& p, double cosine) {
    const Eigen::RowVector3d normal = area_vector(p, faces, f), around = corners(surface, faces, f);
    return normal.dot(around) >= cosine * normal.norm() * around.norm();
  };
  int count = 0;
  // Putting one face back can let a neighbour fit: a few passes.
  for (int pass = 0; pass < 3; ++pass) {
    const int before = count;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d original = area_vector(input, faces, f);
      if (original.squaredNorm() == 0 || original.dot(area_vector(result, faces, f)) >= 0) continue;
      if (original.dot(corners(input_normals, faces, f)) < 0) continue;  // a fold of the input: rightly turned
      Eigen::Matrix3d kept;
      for (int k = 0; k < 3; ++k) {
        kept.row(k) = result.row(faces(f, k));
        result.row(faces(f, k)) = input.row(faces(f, k));
      }
      bool ok = fits(f, result, min_cosine);
      for (int k = 0; k < 3 && ok; ++k)
        for (const int* g = faces_of.begin(faces(f, k)); g != faces_of.end(faces(f, k)); ++g)
          if (*g != f && !fits(*g, result, 0)) {
            ok = false;
            break;
          }
      if (ok) {
        ++count;
      } else {
        for (int k = 0; k < 3; ++k) result.row(faces(f, k)) = kept.row(k);
      }
    }
    if (count == before) break;
  }
  return count;
}

int unturn_few_turned_faces(const Positions& input, const Faces& faces, double max_share, Positions& result) {
  // Unnormalised sums: the folds the harness leaves out of its count of faces turned over
  // (docs/quality.md), so that those two agree.
  const Positions input_normals = summed_area_vectors(input, faces);
  auto folded_in_input = [&](Eigen::Index f) { return area_vector(input, faces, f).dot(corners(input_normals, faces, f)) < 0; };
  auto turned = [&](Eigen::Index f) { return area_vector(input, faces, f).dot(area_vector(result, faces, f)) < 0; };
  std::vector<int> candidates;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (area_vector(input, faces, f).squaredNorm() > 0 && turned(f) && !folded_in_input(f)) candidates.push_back(static_cast<int>(f));
  if (candidates.empty() || static_cast<double>(candidates.size()) > max_share * static_cast<double>(faces.rows())) return 0;

  const Positions surface = area_weighted_vertex_normals(result, faces);  // kept as it was before any move
  auto against = [&](Eigen::Index f) { return area_vector(result, faces, f).dot(corners(surface, faces, f)) < 0; };
  const VertexFaces faces_of = vertex_faces(faces, input.rows());
  auto faces_around = [&](const std::vector<int>& vertices) {
    std::vector<int> out;
    for (int v : vertices) out.insert(out.end(), faces_of.begin(v), faces_of.end(v));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  int count = 0;
  // Un-turning one face can free a neighbour's move: a few passes.
  for (int pass = 0; pass < 3; ++pass) {
    const int before = count;
    for (int f : candidates) {
      if (!turned(f)) continue;
      std::vector<int> moved = {faces(f, 0), faces(f, 1), faces(f, 2)};
      for (int reach = 0; reach < 2; ++reach) {
        if (reach == 1) {  // the face's vertices and their neighbours
          std::vector<int> wider;
          for (int g : faces_around(moved))
            for (int k = 0; k < 3; ++k) wider.push_back(faces(g, k));
          std::sort(wider.begin(), wider.end());
          wider.erase(std::unique(wider.begin(), wider.end()), wider.end());
          moved.swap(wider);
        }
        const std::vector<int> around = faces_around(moved);
        std::vector<unsigned char> was_turned(around.size()), was_against(around.size());
        for (size_t a = 0; a < around.size(); ++a) {
          was_turned[a] = turned(around[a]);
          was_against[a] = against(around[a]) || folded_in_input(around[a]);
        }
        Positions kept(moved.size(), 3);
        for (size_t m = 0; m < moved.size(); ++m) kept.row(m) = result.row(moved[m]);
        bool ok = false;
        for (int step = 1; step <= 20 && !ok; ++step) {
          const double t = step / 20.0;
          for (size_t m = 0; m < moved.size(); ++m) result.row(moved[m]) = kept.row(m) + t * (input.row(moved[m]) - kept.row(m));
          if (turned(f)) continue;
          ok = true;
          for (size_t a = 0; a < around.size() && ok; ++a)
            if (around[a] != f && ((!was_turned[a] && turned(around[a])) || (!was_against[a] && against(around[a])))) ok = false;
        }
        if (ok) {
          ++count;
          break;
        }
        for (size_t m = 0; m < moved.size(); ++m) result.row(moved[m]) = kept.row(m);
      }
    }
    if (count == before) break;
  }
  return count;
}

}  // namespace hht
