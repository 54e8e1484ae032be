#include "engine/bake/bake_manifest.h"

#include "planet/core/hash.h"

#include <cstring>

#include <fmt/format.h>

namespace globe {

std::uint64_t elevationModelHash(const gpu::ElevationParams& params, const std::vector<ElevationSource>& sources) {
  unsigned char bytes[sizeof(params)];
  std::memcpy(bytes, &params, sizeof(params));
  std::uint64_t h = 0;
  for (std::size_t k = 0; k < sizeof(bytes); ++k) h = mix64(h ^ bytes[k]);
  for (const ElevationSource& s : sources) {
    const std::string text = fmt::format("{}|{}|{}|{}|{:a}|{:a}|{:a}", s.path, noDataModeName(s.nodata), s.amplify,
                                         s.priority, s.vertical_scale, s.vertical_offset_m, s.blend_m);
    for (unsigned char c : text) h = mix64(h ^ c);
  }
  return h;
}

namespace {
// Planet names are user text: JSON-escape quotes, backslashes and control characters.
std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      out += fmt::format("\\u{:04x}", c);
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}
}  // namespace

std::string bakeJson(const BakeDescription& b) {
  return fmt::format(
      "{{\n  \"format\": \"{}\",\n  \"levels\": [{}, {}],\n  \"region\": [{:.17g}, {:.17g}, {:.17g}, {:.17g}],\n"
      "  \"planet\": {},\n  \"radius_m\": {:.17g},\n  \"model_hash\": \"{:016x}\"\n}}\n",
      bakeFormatName(b.format), b.levels.first, b.levels.last, b.region.west_deg, b.region.south_deg, b.region.east_deg,
      b.region.north_deg, jsonString(b.planet_name), b.radius_m, b.model_hash);
}

std::string layerJson(const BakeDescription& b, const BakePlan& plan) {
  std::string available;
  for (int level = 0; level <= b.levels.last; ++level) {
    available += level == 0 ? "\n    " : ",\n    ";
    const TileRange* r = nullptr;
    for (const TileRange& candidate : plan.ranges())
      if (candidate.level == level) r = &candidate;
    if (r == nullptr) {
      available += "[]";
    } else {
      available +=
          fmt::format("[{{\"startX\": {}, \"startY\": {}, \"endX\": {}, \"endY\": {}}}]", r->x0, r->y0, r->x1, r->y1);
    }
  }
  return fmt::format(
      "{{\n  \"tilejson\": \"2.1.0\",\n  \"name\": {},\n  \"description\": \"baked by globe bake\",\n"
      "  \"version\": \"1.0.0\",\n  \"format\": \"quantized-mesh-1.0\",\n  \"scheme\": \"tms\",\n"
      "  \"tiles\": [\"{{z}}/{{x}}/{{y}}.terrain\"],\n  \"projection\": \"EPSG:4326\",\n"
      "  \"bounds\": [-180.0, -90.0, 180.0, 90.0],\n  \"minzoom\": 0,\n  \"maxzoom\": {},\n"
      "  \"extensions\": [\"octvertexnormals\"],\n  \"globe_radius_m\": {:.17g},\n{}  \"available\": [{}\n  ]\n}}\n",
      jsonString(b.planet_name), b.levels.last, b.radius_m,
      b.flattening == 0.0 ? std::string() : fmt::format("  \"globe_flattening\": {:.17g},\n", b.flattening), available);
}

}  // namespace globe
