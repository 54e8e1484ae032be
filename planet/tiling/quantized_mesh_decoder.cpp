#include "planet/tiling/quantized_mesh_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

namespace globe {

namespace {

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  bool read(T& out) {
    if (pos_ + sizeof(T) > bytes_.size()) return false;
    std::memcpy(&out, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  bool vec(glm::dvec3& v) { return read(v.x) && read(v.y) && read(v.z); }
  void align(std::size_t n) { pos_ = (pos_ + n - 1) / n * n; }
  bool atEnd() const { return pos_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

bool readDeltas(Reader& r, std::uint32_t count, std::vector<int>& out) {
  int value = 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    std::uint16_t zz = 0;
    if (!r.read(zz)) return false;
    value += (zz >> 1) ^ -(zz & 1);
    out.push_back(value);
  }
  return true;
}

bool readIndex(Reader& r, bool wide, std::uint32_t& out) {
  if (wide) return r.read(out);
  std::uint16_t narrow = 0;
  if (!r.read(narrow)) return false;
  out = narrow;
  return true;
}

glm::dvec3 octDecode(std::uint8_t bx, std::uint8_t by) {
  double x = bx / 255.0 * 2.0 - 1.0, y = by / 255.0 * 2.0 - 1.0;
  double z = 1.0 - std::abs(x) - std::abs(y);
  if (z < 0.0) {
    const double ox = x;
    x = (1.0 - std::abs(y)) * (ox >= 0.0 ? 1.0 : -1.0);
    y = (1.0 - std::abs(ox)) * (y >= 0.0 ? 1.0 : -1.0);
  }
  return glm::normalize(glm::dvec3(x, y, z));
}

bool readExtensions(Reader& r, DecodedMesh& m) {
  while (!r.atEnd()) {
    std::uint8_t id = 0;
    std::uint32_t length = 0;
    if (!r.read(id) || !r.read(length)) return false;
    if (id != 1 || length != m.u.size() * 2) return false;
    for (std::size_t k = 0; k < m.u.size(); ++k) {
      std::uint8_t x = 0, y = 0;
      if (!r.read(x) || !r.read(y)) return false;
      m.normals.push_back(octDecode(x, y));
    }
    m.has_normals = true;
  }
  return true;
}

}  // namespace

std::optional<DecodedMesh> decodeQuantizedMesh(const std::string& bytes, std::string* why) {
  auto fail = [why](const char* what) -> std::optional<DecodedMesh> {
    if (why) *why = what;
    return std::nullopt;
  };
  Reader r(bytes);
  DecodedMesh m;
  std::uint32_t vertices = 0, triangles = 0;
  if (!r.vec(m.center) || !r.read(m.min_height) || !r.read(m.max_height) || !r.vec(m.sphere_center) ||
      !r.read(m.sphere_radius) || !r.vec(m.horizon_point) || !r.read(vertices))
    return fail("truncated header");
  // Heights enter the terrain from here: inf made a tile of infinite bounds (physics never ended).
  // 1000 km is the raster sources' limit too (kMaxRasterValue).
  if (!(std::abs(m.min_height) <= 1.0e6f && std::abs(m.max_height) <= 1.0e6f && m.min_height <= m.max_height))
    return fail("header heights are not finite, beyond 1000 km or out of order");
  if (!readDeltas(r, vertices, m.u) || !readDeltas(r, vertices, m.v) || !readDeltas(r, vertices, m.h))
    return fail("truncated vertex data");
  for (const std::vector<int>* values : {&m.u, &m.v, &m.h})
    for (int value : *values)
      if (value < 0 || value > 32767) return fail("vertex coordinate outside [0, 32767]");
  const bool wide = vertices > 65536;
  r.align(wide ? 4 : 2);
  if (!r.read(triangles)) return fail("truncated triangle count");
  std::uint32_t highest = 0;
  for (std::uint32_t k = 0; k < triangles * 3; ++k) {
    std::uint32_t code = 0;
    if (!readIndex(r, wide, code) || code > highest || highest - code >= vertices)
      return fail("bad high-water-mark index");
    m.indices.push_back(highest - code);
    if (code == 0) ++highest;
  }
  for (auto& edge : m.edges) {
    std::uint32_t count = 0;
    if (!r.read(count)) return fail("truncated edge count");
    for (std::uint32_t k = 0; k < count; ++k) {
      std::uint32_t index = 0;
      if (!readIndex(r, wide, index) || index >= vertices) return fail("bad edge index");
      edge.push_back(index);
    }
  }
  if (!readExtensions(r, m)) return fail("bad extension");
  return m;
}

namespace {

// Writes, at every grid point still NaN, the height of the first triangle of the given orientation
// that holds it (points on an edge count as inside, within 1e-9 of the tile).
void fillFromTriangles(const DecodedMesh& m, int cells, bool clockwise, std::vector<double>& out) {
  const std::size_t side = std::size_t(cells) + 1;
  const double perCell = 32767.0 / cells, tolerance = 1e-9;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const double ua = m.u[a], va = m.v[a], ub = m.u[b], vb = m.v[b], uc = m.u[c], vc = m.v[c];
    const double det = (vb - vc) * (ua - uc) + (uc - ub) * (va - vc);
    if (!(clockwise ? det < 0.0 : det > 0.0)) continue;
    const int iMin = std::max(0, int(std::ceil(std::min({ua, ub, uc}) / perCell - 1e-6)));
    const int iMax = std::min(cells, int(std::floor(std::max({ua, ub, uc}) / perCell + 1e-6)));
    const int jMin = std::max(0, int(std::ceil(std::min({va, vb, vc}) / perCell - 1e-6)));
    const int jMax = std::min(cells, int(std::floor(std::max({va, vb, vc}) / perCell + 1e-6)));
    for (int j = jMin; j <= jMax; ++j) {
      for (int i = iMin; i <= iMax; ++i) {
        const double u = i * perCell, v = j * perCell;
        const double la = ((vb - vc) * (u - uc) + (uc - ub) * (v - vc)) / det;
        const double lb = ((vc - va) * (u - uc) + (ua - uc) * (v - vc)) / det;
        const double lc = 1.0 - la - lb;
        double& h = out[std::size_t(j) * side + std::size_t(i)];
        if (la < -tolerance || lb < -tolerance || lc < -tolerance || !std::isnan(h)) continue;
        h = la * m.height_m(a) + lb * m.height_m(b) + lc * m.height_m(c);
      }
    }
  }
}

}  // namespace

std::vector<double> meshHeightsOnGrid(const DecodedMesh& m, int cells) {
  std::vector<double> out(std::size_t(cells + 1) * std::size_t(cells + 1), std::numeric_limits<double>::quiet_NaN());
  // Counter-clockwise triangles first; a simplified mesh can fold over itself in u/v on steep
  // ground, and its clockwise (folded) triangles only answer where no other does.
  fillFromTriangles(m, cells, false, out);
  if (std::any_of(out.begin(), out.end(), [](double h) { return std::isnan(h); }))
    fillFromTriangles(m, cells, true, out);
  return out;
}

}  // namespace globe
