#pragma once
// The fonts compiled into the program (cmake/EmbedFile.cmake, from Debian's fonts-dejavu-core at
// build time): DejaVu Sans, regular and bold, which cover Latin, Greek and Cyrillic, so track
// names such as "Zürich" or "Škofja Loka" render the same on every machine. The DejaVu licence
// (Bitstream Vera terms) allows embedding the fonts in software.

#include <span>

namespace trailray::scene::detail {

std::span<const unsigned char> dejavu_sans_font();       // DejaVuSans.ttf
std::span<const unsigned char> dejavu_sans_bold_font();  // DejaVuSans-Bold.ttf

}  // namespace trailray::scene::detail
