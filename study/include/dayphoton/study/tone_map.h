// Tone mapping of radiance pictures for viewing (`dayphoton render`'s PNG beside its EXR).
#pragma once

#include "dayphoton/study/image_files.h"

namespace dayphoton::study {

/// Tone mapping for viewing: luminance L = 179 (0.265 R + 0.670 G + 0.065 B); Reinhard et
/// al.'s global operator (SIGGRAPH 2002, eq. 3-4: key a = 0.18 over the log-average
/// luminance, Ld = Ls (1 + Ls / Lwhite^2) / (1 + Ls), Lwhite = the largest scaled luminance
/// after discarding the brightest 0.1 % of pixels), colours scaled by Ld / L, then the sRGB
/// transfer function. Non-finite or negative pixels are shown black. Throws
/// std::invalid_argument without R, G and B channels.
RgbaImage tone_map(const FloatImage& rgb);

}  // namespace dayphoton::study
