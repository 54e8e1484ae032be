#include "engine/render/terrain_warnings.h"

#include <string_view>

namespace globe {

namespace {
bool replace(std::string& text, std::string_view what, std::string_view with) {
  const std::size_t at = text.find(what);
  if (at == std::string::npos) return false;
  text.replace(at, what.size(), with);
  return true;
}
}  // namespace

std::string inOptionTerms(std::string warning) {
  if (replace(warning, "raise the VRAM budget", "raise --vram-mib")) return warning;
  if (replace(warning, "raise the imagery budget", "raise --imagery-mib")) return warning;
  if (replace(warning, "raise the RAM budget", "use a larger --tolerance or a coarser --quality")) return warning;
  if (warning.starts_with("frame budget reached"))
    warning += "; raise --max-nodes or --max-triangles, or use a larger --tolerance";
  return warning;
}

std::vector<std::string> TerrainWarnings::takeNew(const Terrain& terrain) {
  const std::span<const std::string> all = terrain.warnings();
  const std::size_t first = taken_ < all.size() ? taken_ : all.size();
  taken_ = all.size();
  std::vector<std::string> out;
  for (const std::string& warning : all.subspan(first)) out.push_back(inOptionTerms(warning));
  return out;
}

}  // namespace globe
