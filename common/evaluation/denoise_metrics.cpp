#include "evaluation/denoise_metrics.h"

#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace hht {

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;
constexpr double kSkipped = -1.0;  // a face error left out of the means

void check_input(const Positions& result, const Positions& reference, const Faces& faces) {
  if (result.rows() != reference.rows())
    throw std::invalid_argument("denoise metrics: result and reference differ in vertex count");
  if (faces.size() > 0 && (faces.minCoeff() < 0 || faces.maxCoeff() >= reference.rows()))
    throw std::invalid_argument("denoise metrics: face index out of range");
}

Vec3 vertex(const Positions& p, int i) { return p.row(i).transpose(); }

// The area vector of (a, b, c), or false when the area is zero up to rounding: the cross
// product of collinear edges is not exactly zero in floating point.
bool face_normal(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& normal) {
  normal = (b - a).cross(c - a);
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return normal.norm() > 1e-12 * longest;
}

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0) return a;
  return a + std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) * ab;
}

// Projection onto the plane when it falls inside the triangle, else the nearest edge point;
// a degenerate triangle is just its three edges.
double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 n;
  if (face_normal(a, b, c, n)) {
    const double n2 = n.squaredNorm();
    const Vec3 q = p - n * (n.dot(p - a) / n2);
    const double u = n.dot((b - q).cross(c - q)) / n2;
    const double v = n.dot((c - q).cross(a - q)) / n2;
    if (u >= 0 && v >= 0 && u + v <= 1) return (p - q).squaredNorm();
  }
  return std::min({(p - closest_on_segment(p, a, b)).squaredNorm(), (p - closest_on_segment(p, b, c)).squaredNorm(),
                   (p - closest_on_segment(p, c, a)).squaredNorm()});
}

struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -Vec3::Constant(std::numeric_limits<double>::infinity());
  void extend(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  double squared_distance(const Vec3& p) const { return (lo - p).cwiseMax(p - hi).cwiseMax(Vec3::Zero()).squaredNorm(); }
};

// A bounding-volume hierarchy over the triangles (median splits along the longest axis of
// the centroids), answering nearest-triangle queries by branch and bound.
class TriangleTree {
 public:
  TriangleTree(const Positions& positions, const Faces& faces) : p_(positions), f_(faces) {
    const int m = static_cast<int>(faces.rows());
    order_.resize(m);
    centroid_.resize(m);
    for (int i = 0; i < m; ++i) {
      order_[i] = i;
      centroid_[i] = (corner(i, 0) + corner(i, 1) + corner(i, 2)) / 3.0;
    }
    nodes_.reserve(2 * m / kLeafSize + 2);
    if (m > 0) build(0, m);
  }

  double squared_distance_to_face(const Vec3& q, int face) const {
    return squared_distance_to_triangle(q, corner(face, 0), corner(face, 1), corner(face, 2));
  }

  // Squared distance from q to the nearest triangle; `bound` is a known upper bound (the
  // distance to some triangle), which prunes most of the tree at once.
  double squared_distance(const Vec3& q, double bound) const {
    double best = bound;
    std::vector<int> stack;
    if (!nodes_.empty()) stack.push_back(0);
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (node.box.squared_distance(q) >= best) continue;
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k)
          best = std::min(best, squared_distance_to_face(q, order_[k]));
        continue;
      }
      const double dl = nodes_[node.left].box.squared_distance(q);
      const double dr = nodes_[node.right].box.squared_distance(q);
      const int near = dl <= dr ? node.left : node.right;
      const int far = dl <= dr ? node.right : node.left;
      if (std::max(dl, dr) < best) stack.push_back(far);
      if (std::min(dl, dr) < best) stack.push_back(near);  // popped first
    }
    return best;
  }

 private:
  static constexpr int kLeafSize = 4;
  struct Node {
    Box box;
    int first = 0, count = 0;  // the node's triangles are order_[first, first + count)
    int left = -1, right = -1;  // children; -1 for a leaf
  };

  Vec3 corner(int face, int k) const { return vertex(p_, f_(face, k)); }

  int build(int first, int count) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Box box, centroids;
    for (int k = first; k < first + count; ++k) {
      for (int c = 0; c < 3; ++c) box.extend(corner(order_[k], c));
      centroids.extend(centroid_[order_[k]]);
    }
    nodes_[index].box = box;
    nodes_[index].first = first;
    nodes_[index].count = count;
    if (count <= kLeafSize) return index;
    int axis = 0;
    (centroids.hi - centroids.lo).maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int a, int b) { return centroid_[a][axis] < centroid_[b][axis]; });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[index].left = left;  // not a reference held across build(): nodes_ may reallocate
    nodes_[index].right = right;
    return index;
  }

  const Positions& p_;
  const Faces& f_;
  std::vector<int> order_;
  std::vector<Vec3> centroid_;
  std::vector<Node> nodes_;
};

// One face incident to each vertex, or -1 for vertices of no face.
std::vector<int> some_incident_face(const Faces& faces, Eigen::Index vertex_count) {
  std::vector<int> face_of(vertex_count, -1);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) face_of[faces(f, k)] = static_cast<int>(f);
  return face_of;
}

std::vector<double> face_normal_errors(const Positions& result, const Positions& reference, const Faces& faces) {
  std::vector<double> error(faces.rows(), kSkipped);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    Vec3 nr, nx;
    if (!face_normal(vertex(reference, faces(f, 0)), vertex(reference, faces(f, 1)), vertex(reference, faces(f, 2)), nr))
      continue;
    if (!face_normal(vertex(result, faces(f, 0)), vertex(result, faces(f, 1)), vertex(result, faces(f, 2)), nx)) {
      error[f] = 90.0;
      continue;
    }
    // atan2 keeps small angles accurate, where acos of a dot product near 1 does not.
    error[f] = std::atan2(nr.cross(nx).norm(), nr.dot(nx)) * 180.0 / kPi;
  }
  return error;
}

}  // namespace

double mean_face_normal_error_degrees(const Positions& result, const Positions& reference, const Faces& faces) {
  check_input(result, reference, faces);
  double sum = 0;
  int count = 0;
  for (double e : face_normal_errors(result, reference, faces)) {
    if (e == kSkipped) continue;
    sum += e;
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

int flipped_faces(const Positions& result, const Positions& reference, const Faces& faces) {
  check_input(result, reference, faces);
  const auto area = [&](const Positions& p, Eigen::Index f) {
    const Eigen::RowVector3d a = p.row(faces(f, 0));
    return Eigen::RowVector3d((p.row(faces(f, 1)) - a).cross(p.row(faces(f, 2)) - a));
  };
  const std::vector<unsigned char> folded = folded_faces(reference, faces);
  int flipped = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    flipped += !folded[static_cast<size_t>(f)] && area(reference, f).dot(area(result, f)) < 0;
  return flipped;
}

Eigen::VectorXd vertex_normal_error_degrees(const Positions& result, const Positions& reference, const Faces& faces) {
  check_input(result, reference, faces);
  const std::vector<double> error = face_normal_errors(result, reference, faces);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(result.rows());
  Eigen::VectorXi count = Eigen::VectorXi::Zero(result.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    if (error[f] == kSkipped) continue;
    for (int k = 0; k < 3; ++k) {
      sum[faces(f, k)] += error[f];
      ++count[faces(f, k)];
    }
  }
  for (Eigen::Index i = 0; i < sum.size(); ++i)
    if (count[i] > 0) sum[i] /= count[i];
  return sum;
}

Eigen::VectorXd vertex_distance_to_reference(const Positions& result, const Positions& reference, const Faces& faces) {
  check_input(result, reference, faces);
  const TriangleTree tree(reference, faces);
  const std::vector<int> face_of = some_incident_face(faces, result.rows());
  Eigen::VectorXd distance = Eigen::VectorXd::Zero(result.rows());
  for (Eigen::Index i = 0; i < result.rows(); ++i) {
    if (face_of[i] < 0) continue;
    // The vertex's own reference face bounds the search: the result is usually close to it.
    const Vec3 q = vertex(result, static_cast<int>(i));
    distance[i] = std::sqrt(tree.squared_distance(q, tree.squared_distance_to_face(q, face_of[i])));
  }
  return distance;
}

double mean_distance_to_reference(const Positions& result, const Positions& reference, const Faces& faces) {
  const Eigen::VectorXd distance = vertex_distance_to_reference(result, reference, faces);
  const std::vector<int> face_of = some_incident_face(faces, reference.rows());
  Box box;
  double sum = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < reference.rows(); ++i) {
    if (face_of[i] < 0) continue;
    box.extend(vertex(reference, static_cast<int>(i)));
    sum += distance[i];
    ++count;
  }
  if (count == 0) return 0.0;
  const double diagonal = (box.hi - box.lo).norm();
  return diagonal > 0 ? sum / count / diagonal : sum / count;
}

}  // namespace hht
