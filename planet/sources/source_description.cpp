#include "planet/sources/source_description.h"

namespace globe {

std::string_view noDataModeName(NoDataMode mode) { return mode == NoDataMode::kHole ? "hole" : "fill"; }

}  // namespace globe
