#include "engine/io/exr_stream.h"

#include <Iex.h>

#include <string_view>

namespace globe {

CheckedExrStream::CheckedExrStream(const std::string& path, const std::string& errorPath)
    : Imf::OStream(path.c_str()), file_(path, errorPath) {}

void CheckedExrStream::write(const char c[], int n) {
  if (!file_.write(std::string_view(c, size_t(n)))) throw Iex::IoExc(file_.errorMessage());
}

void CheckedExrStream::seekp(uint64_t pos) {
  if (!file_.seek(pos)) throw Iex::IoExc(file_.errorMessage());
}

}  // namespace globe
