// render_mesh: pictures of meshes for the docs, by a small software z-buffer rasteriser (no
// OpenGL, so it runs headless). Flat shading per face, so that a sharp edge shows as a jump in
// brightness: a reader can see whether a denoiser kept the cube's or Fandisk's edges.
//
//   render_mesh [--azimuth A] [--elevation E] [--size S] [--perspective] [--wireframe]
//               [--title "a|b|..."] out.png mesh1 [mesh2 ...]
//
// Each mesh gets its own S x S panel, side by side, with its title (the file's base name unless
// --title gives them) underneath. All panels share one camera framed on the first mesh's
// bounding box, so the panels compare like for like. The camera looks at the box centre from
// azimuth A (degrees about the y axis, 0 on the +z side, growing towards +x) and elevation E
// (degrees above the x-z plane); y is up. Orthographic unless --perspective (30 degree field
// of view); --wireframe draws the triangles' edges in black. Anti-aliasing: each panel is
// rendered at 2S x 2S and averaged down 2 x 2. Defaults: azimuth 35, elevation 25, size 600.
//
// Angles that show data/fandisk.off's sharp edges best (it lies "upside down" for y up):
// --azimuth 210 --elevation -45 (the stepped arcs, the outer edges and the smooth valley that
// must stay smooth), or --azimuth 150 --elevation -20; the default view suits the cube.
#include "bench_util.h"

#include <QFont>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

struct Options {
  double azimuth = 35, elevation = 25;
  int size = 600;
  bool perspective = false, wireframe = false;
  std::vector<std::string> titles;
  std::string output;
  std::vector<std::string> meshes;
};

struct Mesh {
  hht::Positions positions;
  hht::Faces faces;
};

// Maps world points to pixels of a square image of `pixels` side, with a depth key that grows
// towards the viewer and is affine in screen space (view depth for orthographic, 1 / distance
// for perspective), so it can be interpolated with screen-space barycentric coordinates.
struct Camera {
  Vec3 centre, right, up, back;  // back points from the centre towards the eye
  bool perspective = false;
  double eye_distance = 0;  // perspective only: outside the box's bounding sphere
  double scale = 1;         // pixels per unit of view-plane extent (per unit of x / z in perspective)
  double pixels = 0;

  static constexpr double kMargin = 1.15;  // room for noise beyond the framed box
  static constexpr double kHalfFov = 15 * kPi / 180;

  Camera(const hht::Positions& framed, double azimuth, double elevation, bool perspective_view, int image_pixels)
      : perspective(perspective_view), pixels(image_pixels) {
    const Vec3 lo = framed.colwise().minCoeff().transpose(), hi = framed.colwise().maxCoeff().transpose();
    centre = (lo + hi) / 2;
    const double a = azimuth * kPi / 180, e = elevation * kPi / 180;
    back = Vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    // Looking straight down or up, "up" on the screen is taken from the azimuth instead.
    const Vec3 world_up =
        std::abs(std::cos(e)) > 1e-6 ? Vec3(Vec3::UnitY()) : Vec3(Vec3(-std::sin(a), 0, -std::cos(a)) * std::sin(e));
    right = world_up.cross(back).normalized();
    up = back.cross(right);
    eye_distance = std::max((hi - lo).norm() / 2, 1e-300) / std::sin(kHalfFov);
    // Fit the box's eight projected corners, not its bounding sphere: flat parts fill the panel.
    double extent = 0;
    for (int k = 0; k < 8; ++k) {
      const Vec3 corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
      const Vec3 d = corner - centre;
      const double z = perspective ? eye_distance - d.dot(back) : 1.0;
      extent = std::max({extent, std::abs(d.dot(right)) / z, std::abs(d.dot(up)) / z});
    }
    scale = pixels / (2 * kMargin * (extent > 0 ? extent : 1.0));
  }

  Vec3 eye() const { return centre + eye_distance * back; }

  // Pixel x (right), pixel y (down), depth key; false behind the eye.
  bool project(const Vec3& p, double& x, double& y, double& key) const {
    const Vec3 d = p - centre;
    double s = scale;
    key = d.dot(back);
    if (perspective) {
      const double z = eye_distance - key;
      if (z <= 1e-9 * eye_distance) return false;
      s /= z;
      key = 1 / z;
    }
    x = pixels / 2 + s * d.dot(right);
    y = pixels / 2 - s * d.dot(up);
    return true;
  }

  // The unit vector from p towards the viewer.
  Vec3 to_viewer(const Vec3& p) const { return perspective ? Vec3((eye() - p).normalized()) : back; }
};

// Linear RGB in [0, 1], one triple per pixel, with its z-buffer.
struct Canvas {
  int side;
  std::vector<float> rgb, depth;
  explicit Canvas(int s)
      : side(s), rgb(3 * size_t(s) * s, 1.0f), depth(size_t(s) * s, -std::numeric_limits<float>::infinity()) {}
};

// Flat shading: a headlight (brightness by how squarely a face looks at the viewer) plus a
// faint key light from the upper left, so that faces at equal angles to the view still differ.
Vec3 face_colour(const Vec3& normal, const Vec3& to_viewer, const Camera& camera) {
  const Vec3 n = normal.dot(to_viewer) < 0 ? Vec3(-normal) : normal;  // both sides lit
  const Vec3 key = (-0.6 * camera.right + 0.7 * camera.up + 0.4 * camera.back).normalized();
  const double head = n.dot(to_viewer);
  const double shade = 0.12 + 0.66 * head * head + 0.22 * std::max(0.0, n.dot(key));
  return shade * Vec3(0.80, 0.83, 0.90);
}

void draw_mesh(const Mesh& mesh, const Camera& camera, bool wireframe, Canvas& canvas) {
  const int n = static_cast<int>(mesh.positions.rows());
  std::vector<double> sx(n), sy(n), key(n);
  std::vector<char> visible(n);
  for (int i = 0; i < n; ++i) visible[i] = camera.project(mesh.positions.row(i).transpose(), sx[i], sy[i], key[i]);
  const double line = 1.4;  // wireframe width, in pixels of the 2x canvas

  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const int v[3] = {mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)};
    if (!visible[v[0]] || !visible[v[1]] || !visible[v[2]]) continue;
    const Vec3 a = mesh.positions.row(v[0]), b = mesh.positions.row(v[1]), c = mesh.positions.row(v[2]);
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.squaredNorm() == 0) continue;
    const Vec3 colour = face_colour(normal.normalized(), camera.to_viewer((a + b + c) / 3), camera);

    // Twice the signed screen area; below, e[k] is a pixel's barycentric coordinate for corner k
    // (the edge function of the opposite edge over `area`), so e[k] |area| / length is the
    // pixel's distance to that edge.
    const double area = (sx[v[1]] - sx[v[0]]) * (sy[v[2]] - sy[v[0]]) - (sy[v[1]] - sy[v[0]]) * (sx[v[2]] - sx[v[0]]);
    if (std::abs(area) < 1e-12) continue;  // seen edge-on
    double edge_length[3];
    for (int k = 0; k < 3; ++k) {
      const int p = v[(k + 1) % 3], q = v[(k + 2) % 3];
      edge_length[k] = std::hypot(sx[q] - sx[p], sy[q] - sy[p]);
    }
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({sx[v[0]], sx[v[1]], sx[v[2]]}))));
    const int x1 = std::min(canvas.side - 1, static_cast<int>(std::ceil(std::max({sx[v[0]], sx[v[1]], sx[v[2]]}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({sy[v[0]], sy[v[1]], sy[v[2]]}))));
    const int y1 = std::min(canvas.side - 1, static_cast<int>(std::ceil(std::max({sy[v[0]], sy[v[1]], sy[v[2]]}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        double e[3];
        for (int k = 0; k < 3; ++k) {
          const int p = v[(k + 1) % 3], q = v[(k + 2) % 3];
          e[k] = ((sx[q] - sx[p]) * (py - sy[p]) - (sy[q] - sy[p]) * (px - sx[p])) / area;  // barycentric
        }
        if (e[0] < 0 || e[1] < 0 || e[2] < 0) continue;
        const double z = e[0] * key[v[0]] + e[1] * key[v[1]] + e[2] * key[v[2]];
        const size_t pixel = size_t(y) * canvas.side + x;
        if (z <= canvas.depth[pixel]) continue;
        canvas.depth[pixel] = static_cast<float>(z);
        bool on_edge = false;
        for (int k = 0; k < 3 && wireframe; ++k)
          on_edge = on_edge || e[k] * std::abs(area) / edge_length[k] < line;
        for (int ch = 0; ch < 3; ++ch) canvas.rgb[3 * pixel + ch] = on_edge ? 0.05f : static_cast<float>(colour[ch]);
      }
  }
}

// Averages 2 x 2 blocks of `canvas` into `image` at (left, top); linear to sRGB on the way.
void downscale_into(const Canvas& canvas, QImage& image, int left, int top) {
  auto srgb = [](double c) {
    c = std::clamp(c, 0.0, 1.0);
    return static_cast<int>(std::lround(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055)));
  };
  const int side = canvas.side / 2;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      double sum[3] = {0, 0, 0};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (int c = 0; c < 3; ++c) sum[c] += canvas.rgb[3 * (size_t(2 * y + dy) * canvas.side + 2 * x + dx) + c];
      image.setPixel(left + x, top + y, qRgb(srgb(sum[0] / 4), srgb(sum[1] / 4), srgb(sum[2] / 4)));
    }
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == separator)
      parts.emplace_back();
    else
      parts.back() += ch;
  }
  return parts;
}

bool parse(int argc, char** argv, Options& o, std::string& error) {
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
        return argv[++i];
      };
      auto number = [&]() {
        const std::string text = value();
        size_t used = 0;
        double x = 0;
        try {
          x = std::stod(text, &used);
        } catch (const std::exception&) {
        }
        if (used == 0 || used != text.size() || !std::isfinite(x)) throw std::invalid_argument(arg + " needs a number, not " + text);
        return x;
      };
      if (arg == "--azimuth")
        o.azimuth = number();
      else if (arg == "--elevation")
        o.elevation = number();
      else if (arg == "--size")
        o.size = static_cast<int>(std::lround(std::clamp(number(), 0.0, 1e6)));
      else if (arg == "--title")
        o.titles = split(value(), '|');
      else if (arg == "--perspective")
        o.perspective = true;
      else if (arg == "--wireframe")
        o.wireframe = true;
      else if (arg.rfind("--", 0) == 0)
        throw std::invalid_argument("unknown option " + arg);
      else if (o.output.empty())
        o.output = arg;
      else
        o.meshes.push_back(arg);
    }
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  if (o.meshes.empty()) error = "needs an output PNG and at least one mesh";
  else if (o.size < 16 || o.size > 8000) error = "--size must be between 16 and 8000";
  else if (!o.titles.empty() && o.titles.size() != o.meshes.size()) error = "--title needs one title per mesh";
  return error.empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  std::string error;
  if (!parse(argc, argv, o, error)) {
    std::fprintf(stderr,
                 "render_mesh: %s\nusage: render_mesh [--azimuth A] [--elevation E] [--size S] [--perspective] "
                 "[--wireframe] [--title \"a|b\"] out.png mesh1 [mesh2 ...]\n",
                 error.c_str());
    return 2;
  }
  std::vector<Mesh> meshes(o.meshes.size());
  for (size_t i = 0; i < meshes.size(); ++i)
    if (!hht::bench::load_mesh(o.meshes[i], meshes[i].positions, meshes[i].faces) || meshes[i].positions.rows() == 0) {
      std::fprintf(stderr, "render_mesh: cannot read a mesh from %s\n", o.meshes[i].c_str());
      return 1;
    }
  if (o.titles.empty())
    for (const auto& path : o.meshes) o.titles.push_back(std::filesystem::path(path).stem().string());

  // Text needs a QGuiApplication; the offscreen platform needs no display. Our own arguments
  // stay away from Qt, which would take some (-title, -platform) as its own.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  int qt_argc = 1;
  QGuiApplication app(qt_argc, argv);

  const int title_band = std::max(20, o.size / 12);
  QImage image(o.size * static_cast<int>(meshes.size()), o.size + title_band, QImage::Format_RGB32);
  image.fill(Qt::white);
  const Camera camera(meshes[0].positions, o.azimuth, o.elevation, o.perspective, 2 * o.size);
  for (size_t i = 0; i < meshes.size(); ++i) {
    Canvas canvas(2 * o.size);
    draw_mesh(meshes[i], camera, o.wireframe, canvas);
    downscale_into(canvas, image, static_cast<int>(i) * o.size, 0);
  }
  QPainter painter(&image);
  QFont font("DejaVu Sans");
  font.setPixelSize(std::max(10, title_band / 2));
  painter.setFont(font);
  painter.setPen(Qt::black);
  for (size_t i = 0; i < meshes.size(); ++i)
    painter.drawText(QRect(static_cast<int>(i) * o.size, o.size, o.size, title_band), Qt::AlignCenter,
                     QString::fromStdString(o.titles[i]));
  painter.end();
  if (!image.save(QString::fromStdString(o.output))) {
    std::fprintf(stderr, "render_mesh: cannot write %s\n", o.output.c_str());
    return 1;
  }
  return 0;
}
