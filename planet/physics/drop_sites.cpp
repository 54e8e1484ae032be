#include "planet/physics/drop_sites.h"

#include "planet/camera/camera.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/triacontahedron.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

std::string_view dropSiteKindName(DropSiteKind kind) {
  switch (kind) {
    case DropSiteKind::kVertex:
      return "vertex";
    case DropSiteKind::kPole:
      return "pole";
    case DropSiteKind::kSeam:
      return "seam";
    case DropSiteKind::kAntimeridian:
      return "antimeridian";
    case DropSiteKind::kRandom:
      return "random";
    case DropSiteKind::kCluster:
      return "cluster";
  }
  return "random";
}

TangentFrame tangentFrame(const glm::dvec3& up) {
  const glm::dvec3 axis = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 east = glm::normalize(glm::cross(axis, up));
  return {east, glm::cross(up, east)};
}

std::vector<DropSite> specialDropSites() {
  const Triacontahedron& t = Triacontahedron::get();
  const RhombusFaceMapping& mapping = RhombusFaceMapping::get();
  std::vector<DropSite> vertices, seams, antimeridian;
  for (int v = 0; v < kVertexCount; ++v)
    vertices.push_back({t.vertexDirection(v), v == 0 || v == 11 ? DropSiteKind::kPole : DropSiteKind::kVertex});
  // Each seam once: edge e of face f is shared with a face whose own edge is the same segment;
  // take it from the lower face index.
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      if (t.face(f).neighbour[size_t(e)].face < f) continue;
      for (double s : {0.5, 0.25}) {
        const double u = e == 0 ? s : e == 1 ? 1.0 : e == 2 ? 1.0 - s : 0.0;
        const double v = e == 0 ? 0.0 : e == 1 ? s : e == 2 ? 1.0 : 1.0 - s;
        seams.push_back({mapping.unitPoint(f, u, v), DropSiteKind::kSeam});
      }
    }
  }
  for (double lat : {0.0, 30.0, -30.0, 60.0, -60.0})
    for (double lon : {180.0, -179.9999})
      antimeridian.push_back({directionFromLatLon(lat, lon), DropSiteKind::kAntimeridian});
  // Interleave: vertex, seam, antimeridian, vertex, ... with the poles first.
  std::stable_partition(vertices.begin(), vertices.end(),
                        [](const DropSite& s) { return s.kind == DropSiteKind::kPole; });
  std::vector<DropSite> out;
  for (size_t k = 0; out.size() < vertices.size() + seams.size() + antimeridian.size(); ++k) {
    if (k < vertices.size()) out.push_back(vertices[k]);
    if (k < seams.size()) out.push_back(seams[k]);
    if (k < antimeridian.size()) out.push_back(antimeridian[k]);
  }
  return out;
}

namespace {

glm::dvec3 randomDirection(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uz(-1.0, 1.0), uphi(0.0, 6.283185307179586);
  const double z = uz(rng), phi = uphi(rng), r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

std::vector<DropSite> scatteredDropSites(uint32_t count, std::mt19937_64& rng) {
  std::vector<DropSite> sites = specialDropSites();
  if (sites.size() > count) sites.resize(count);
  while (sites.size() < count) sites.push_back({randomDirection(rng), DropSiteKind::kRandom});
  return sites;
}

std::vector<DropSite> clusteredDropSites(uint32_t count, const glm::dvec3& centre, double radius_m,
                                         double sphereRadius_m, std::mt19937_64& rng) {
  const glm::dvec3 up = glm::normalize(centre);
  const auto [east, north] = tangentFrame(up);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<DropSite> sites;
  for (uint32_t k = 0; k < count; ++k) {
    const double arc = radius_m / sphereRadius_m * std::sqrt(unit(rng)), azimuth = 6.283185307179586 * unit(rng);
    const glm::dvec3 d = std::cos(arc) * up + std::sin(arc) * (std::cos(azimuth) * east + std::sin(azimuth) * north);
    sites.push_back({glm::normalize(d), DropSiteKind::kCluster});
  }
  return sites;
}

}  // namespace globe
