#pragma once
// The files a raster source makes GDAL read, checked before GDAL opens any of them: the source
// itself and, through VRTs (which may name VRTs in turn), every SourceFilename. Each must be a
// regular file: a FIFO among them blocked the first read forever, and was reported as "no such
// file". Inside GDAL's archive readers (/vsizip/, /vsigzip/, /vsitar/) the archive is the file checked
// and the member's uncompressed size is bounded; other virtual file systems (network, stdin) are
// refused.
#include "planet/core/error.h"

#include <cstdint>
#include <string>

namespace globe {

// An archive member read through /vsizip/ and the like may not uncompress to more than this (a
// float raster at the pixel limit, kMaxRasterPixels, is 1 GiB; a zip bomb is refused by its header).
inline constexpr std::uint64_t kMaxArchiveMemberBytes = std::uint64_t{2} << 30;

// Ok when `path` and everything it names can be handed to GDAL; otherwise an Error naming the
// source and the offending file ("a.vrt: its source 'fifo.tif' is a FIFO").
Status checkRasterInputs(const std::string& path);

}  // namespace globe
