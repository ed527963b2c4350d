// The standalone PNG of a sky fisheye (sky_mean.png, sky_hour.png): the luminance false colour
// of the fisheye (result_images.h sky_fisheye: zenith at the centre, north up, east LEFT, the
// sky seen from below) in a white margin with the horizon circle and the compass letters N, E,
// S, W just outside it, and below it the legend (image_legend.h): "Sky luminance, cd/m2", the
// logarithmic colour bar and a note saying what the picture shows.
#pragma once

#include <string>

#include "dayphoton/report/colour_scale.h"
#include "dayphoton/study/image_files.h"

namespace dayphoton::report {

/// Where the parts of a sky picture are (pixels of the picture before the legend).
struct SkyPicture {
  study::RgbaImage image;
  int fisheye_x = 0, fisheye_y = 0;  ///< top-left pixel of the fisheye
  int size = 0;                      ///< its width and height
  int letter_box = 0;                ///< margin around it holding the letters
};

/// The fisheye `rgb` (channels R, G, B, A) as false colour of `scale` with the horizon circle
/// and the letters N (top), S (bottom), E (left), W (right) centred in the margin.
SkyPicture sky_picture(const study::FloatImage& rgb, const ColourScale& scale);

/// sky_picture with the legend below it; `note` e.g. "annual mean, seen from below (east left)".
study::RgbaImage sky_png(const study::FloatImage& rgb, const ColourScale& scale, const std::string& note);

}  // namespace dayphoton::report
