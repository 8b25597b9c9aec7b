#include "mesh/cotangent_laplacian.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

namespace {

Eigen::Vector3d row(const Positions& p, int i) { return p.row(i).transpose(); }

// cot of the angle between a and b; |cross| floored relative to |a||b| so that a zero-area
// face contributes a large but finite weight.
double cotangent(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double sine = a.cross(b).norm();
  const double floor = 1e-8 * a.norm() * b.norm();
  return a.dot(b) / std::max(sine, floor > 0 ? floor : 1e-300);
}

}  // namespace

Positions corner_cotangents(const Positions& positions, const Faces& faces) {
  Positions cot(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = row(positions, faces(f, k));
      cot(f, k) = cotangent(row(positions, faces(f, (k + 1) % 3)) - p, row(positions, faces(f, (k + 2) % 3)) - p);
    }
  return cot;
}

double mixed_voronoi_share(const double squared[3], const double cot[3], double area, int k) {
  for (int i = 0; i < 3; ++i)
    if (cot[i] < 0) return area * (k == i ? 0.5 : 0.25);
  const int j = (k + 1) % 3, l = (k + 2) % 3;
  return (squared[l] * cot[l] + squared[j] * cot[j]) / 8.0;
}

Eigen::VectorXd mixed_voronoi_areas(const Positions& positions, const Faces& faces) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(positions.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d p[3] = {row(positions, faces(f, 0)), row(positions, faces(f, 1)), row(positions, faces(f, 2))};
    const double face_area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(face_area > 0)) continue;
    double squared[3], cot[3];
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3, l = (k + 2) % 3;
      squared[k] = (p[l] - p[j]).squaredNorm();
      cot[k] = cotangent(p[j] - p[k], p[l] - p[k]);
    }
    for (int k = 0; k < 3; ++k) area[faces(f, k)] += mixed_voronoi_share(squared, cot, face_area, k);
  }
  return area;
}

CotangentLaplacian extrinsic_cotangent_laplacian(const Positions& positions, const Faces& faces) {
  const Positions cot = corner_cotangents(positions, faces);
  CotangentLaplacian out;
  out.pairs.resize(3 * faces.rows(), 2);
  out.weights.resize(3 * faces.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index e = 3 * f + k;
      out.pairs(e, 0) = faces(f, (k + 1) % 3);
      out.pairs(e, 1) = faces(f, (k + 2) % 3);
      out.weights[e] = 0.5 * cot(f, k);
    }
  out.areas = mixed_voronoi_areas(positions, faces);
  return out;
}

Eigen::SparseMatrix<double> cotangent_matrix(const CotangentLaplacian& laplacian, int vertex_count) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(laplacian.weights.size()) * 4);
  for (Eigen::Index e = 0; e < laplacian.weights.size(); ++e) {
    const int j = laplacian.pairs(e, 0), l = laplacian.pairs(e, 1);
    const double w = laplacian.weights[e];
    entries.emplace_back(j, l, -w);
    entries.emplace_back(l, j, -w);
    entries.emplace_back(j, j, w);
    entries.emplace_back(l, l, w);
  }
  Eigen::SparseMatrix<double> c(vertex_count, vertex_count);
  c.setFromTriplets(entries.begin(), entries.end());
  return c;
}

Positions cotangent_matrix_times(const CotangentLaplacian& laplacian, const Positions& positions) {
  Positions out = Positions::Zero(positions.rows(), 3);
  for (Eigen::Index e = 0; e < laplacian.weights.size(); ++e) {
    const int j = laplacian.pairs(e, 0), l = laplacian.pairs(e, 1);
    const Eigen::RowVector3d d = laplacian.weights[e] * (positions.row(j) - positions.row(l));
    out.row(j) += d;
    out.row(l) -= d;
  }
  return out;
}

}  // namespace hht
