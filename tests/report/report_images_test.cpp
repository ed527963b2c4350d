// Result images (report/result_images.h, study/image_files.h, colour_scale.h): the grid EXR
// files, made from the results model, read back with OpenEXR's own reader equal the CSV tables
// value for value (issue 7 acceptance), lattices of real and rotated grids (study/
// sensor_lattice.h, found by the run), the sky fisheye's geometry, PNGs decoded by libpng, the
// tone mapper, the colour scales and the M/D/H parser.
#include "dayphoton/report/result_images.h"
#include "dayphoton/report/image_legend.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <png.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/result_tables.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/sensor_lattice.h"
#include "dayphoton/study/tone_map.h"
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::study;
using namespace dayphoton::report;
namespace fs = std::filesystem;

namespace {


/// An EXR's channels and attributes, read with OpenEXR directly (not through read_exr).
struct Exr {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> channels;
  Imf::Header header;
};

Exr read_with_openexr(const std::string& path) {
  Imf::InputFile file(path.c_str());
  Exr e;
  e.header = file.header();
  const Imath::Box2i w = e.header.dataWindow();
  e.width = w.max.x - w.min.x + 1;
  e.height = w.max.y - w.min.y + 1;
  Imf::FrameBuffer frame;
  for (auto it = e.header.channels().begin(); it != e.header.channels().end(); ++it) {
    std::vector<float>& plane = e.channels[it.name()];
    plane.assign(static_cast<std::size_t>(e.width * e.height), -1.0f);
    frame.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.data()) - (w.min.x + w.min.y * e.width) * sizeof(float),
                                       sizeof(float), sizeof(float) * static_cast<std::size_t>(e.width)));
  }
  file.setFrameBuffer(frame);
  file.readPixels(w.min.y, w.max.y);
  return e;
}

Vec3 v3(const Imf::Header& h, const char* name) {
  const Imath::V3f v = h.typedAttribute<Imf::V3fAttribute>(name).value();
  return {v.x, v.y, v.z};
}

/// The model of a grid in <results>/<name> with the daylight factor and the per-sensor annual
/// metrics, made by the run's builder (results_model_builder.h).
GridResult grid_model(const std::string& name, const std::vector<SensorPoint>& sensors) {
  SensorGrid grid;
  grid.name = name;
  grid.points = sensors;
  GridResult g = results_grid(grid, name, CaseResult{}, 0, 0);
  add_daylight_factor(g, GridStatistics{}, DaylightFactorUncertainty{});
  AnnualStudy study;
  study.sensors.resize(sensors.size());
  add_annual(g, study, AnnualStudySettings{}, AnnualOutputs{false, true});
  return g;
}

/// A grid folder written with the study's own writers: sensors.csv, daylight_factor.csv and
/// metrics.csv with distinct, irregular values per sensor.
void write_grid_folder(const std::string& dir, const std::vector<SensorPoint>& sensors) {
  fs::create_directories(dir);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> df;
  std::vector<metrics::SensorMetrics> m(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    df.push_back(20 * u(rng));
    m[i].da_percent = 100 * u(rng);
    m[i].udi_original_percent = 100 * u(rng);
    m[i].udi_autonomous_percent = 100 * u(rng);
    m[i].mean_occupied_lux = 5000 * u(rng);
  }
  write_sensors_csv(sensors, {}, dir + "/sensors.csv");
  write_daylight_factor_csv(sensors, df, dir + "/daylight_factor.csv");
  write_metrics_csv(sensors, m, metrics::MetricSettings{}, {}, dir + "/metrics.csv");
}

/// Every EXR written for the grid equals its CSV column at the sensor's pixel (positions from
/// the header's lattice attributes), and has alpha 0 exactly where no sensor is.
void expect_exr_equals_csv(const std::string& dir, const GridResult& grid, std::size_t sensors, bool regular) {
  ASSERT_EQ(grid.quantities.size(), 5u);
  for (const SensorQuantity& q : grid.quantities) {
    SCOPED_TRACE(q.stem);
    const SensorTable table = read_sensor_table(dir + "/" + q.file);
    const Exr exr = read_with_openexr(dir + "/" + q.stem + ".exr");
    ASSERT_EQ(exr.header.typedAttribute<Imf::StringAttribute>("quantity").value(), q.quantity);
    ASSERT_EQ(exr.header.typedAttribute<Imf::StringAttribute>("unit").value(), q.unit);
    ASSERT_EQ(exr.header.typedAttribute<Imf::StringAttribute>("dayphoton:source").value(), q.file + ":" + q.column);
    const std::vector<float>& y = exr.channels.at("Y");
    const std::vector<float>& a = exr.channels.at("A");
    std::vector<int> covered(y.size(), 0);
    const int c = table.column(q.column);
    ASSERT_GE(c, 0);
    ASSERT_EQ(table.rows.size(), sensors);
    for (std::size_t i = 0; i < sensors; ++i) {
      int col = static_cast<int>(i), row = 0;
      if (regular) {
        // Pixel centre (col, row) = origin + col * column_step + row * row_step.
        const Vec3 p{table.rows[i][1], table.rows[i][2], table.rows[i][3]};
        const Vec3 o = v3(exr.header, "dayphoton:origin_m"), cs = v3(exr.header, "dayphoton:column_step_m"),
                   rs = v3(exr.header, "dayphoton:row_step_m");
        const double fc = dot(p - o, cs) / dot(cs, cs), fr = dot(p - o, rs) / dot(rs, rs);
        col = static_cast<int>(std::lround(fc));
        row = static_cast<int>(std::lround(fr));
        ASSERT_NEAR(fc, col, 1e-3);
        ASSERT_NEAR(fr, row, 1e-3);
      }
      ASSERT_GE(col, 0);
      ASSERT_LT(col, exr.width);
      ASSERT_GE(row, 0);
      ASSERT_LT(row, exr.height);
      const std::size_t k = static_cast<std::size_t>(row * exr.width + col);
      EXPECT_EQ(y[k], static_cast<float>(table.rows[i][static_cast<std::size_t>(c)])) << "sensor " << i;
      EXPECT_EQ(a[k], 1.0f);
      ++covered[k];
    }
    for (std::size_t k = 0; k < y.size(); ++k) {
      EXPECT_LE(covered[k], 1);
      if (!covered[k]) {
        EXPECT_EQ(a[k], 0.0f);
        EXPECT_EQ(y[k], 0.0f);
      }
    }
  }
}

/// Decode a PNG with libpng's simplified API into RGBA bytes.
std::vector<std::uint8_t> decode_png(const std::string& bytes, int& width, int& height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) return {};
  image.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) return {};
  width = static_cast<int>(image.width);
  height = static_cast<int>(image.height);
  return pixels;
}

}  // namespace

TEST(ResultImages, OfficeGridExrEqualsTheCsvTables) {
  // The sensors of projects/office (11 x 15 at 0.5 m): one pixel per sensor.
  const project::Project project = project::load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml");
  const SceneDescription scene = project::build_scene_description(project);
  ASSERT_FALSE(scene.grids.empty());
  const std::vector<SensorPoint>& sensors = scene.grids[0].points;
  const std::string results = test::empty_dir("report_images_office"), dir = results + "/workplane";
  fs::create_directories(dir);
  write_grid_folder(dir, sensors);
  const GridResult grid = grid_model("workplane", sensors);
  const std::vector<std::string> written = write_grid_images(results, CaseResult{}, grid);
  EXPECT_EQ(written.size(), 10u);  // 5 quantities x (EXR + PNG)
  const SensorLattice& lattice = grid.lattice;
  ASSERT_TRUE(lattice.regular);
  EXPECT_EQ(lattice.columns, 11);
  EXPECT_EQ(lattice.rows, 15);
  EXPECT_NEAR(lattice.spacing_m, 0.5, 1e-9);
  // Columns run east, rows south: pixel (0, 0) is the north-west sensor.
  EXPECT_NEAR(lattice.column_step_m.x, 0.5, 1e-9);
  EXPECT_NEAR(lattice.row_step_m.y, -0.5, 1e-9);
  expect_exr_equals_csv(dir, grid, sensors.size(), true);
  // The PNG decodes to the plan (32 px per sensor) with the outline, the band of the scale bar
  // and north arrow above it and the legend below it: the image grid_png makes, opaque.
  std::ifstream in(dir + "/daylight_factor.png", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int w = 0, h = 0;
  const std::vector<std::uint8_t> pixels = decode_png(bytes, w, h);
  ASSERT_FALSE(pixels.empty());
  const PlanPicture picture = plan_picture(lattice, std::vector<double>(sensors.size(), 1.0), daylight_factor_scale(),
                                           32, plan_geometry(CaseResult{}, grid));
  EXPECT_TRUE(picture.north_arrow);
  const LegendImage layout = with_legend(picture.image, daylight_factor_scale(), "Daylight factor, %", "1 cell = 0.5 m");
  ASSERT_EQ(w, layout.image.width);
  ASSERT_EQ(h, layout.image.height);
  EXPECT_GT(w, 11 * 32);
  EXPECT_GT(h, 15 * 32 + 60);
  const auto px = [&](int x, int y) {
    const std::size_t k = static_cast<std::size_t>(y * w + x) * 4;
    return std::array<std::uint8_t, 4>{pixels[k], pixels[k + 1], pixels[k + 2], pixels[k + 3]};
  };
  for (int y = 0; y < h; y += 5)
    for (int x = 0; x < w; x += 5) ASSERT_EQ(px(x, y)[3], 255);
  // The outline: the north-west corner and the east edge of the plan are dark, the edge
  // between two sensors is not.
  const int x0 = layout.plan_x + picture.cells_x, y0 = layout.plan_y + picture.cells_y;
  EXPECT_EQ(px(x0, y0), (std::array<std::uint8_t, 4>{OutlineGrey, OutlineGrey, OutlineGrey, 255}));
  EXPECT_EQ(px(x0 + 11 * 32 - 1, y0 + 100)[0], OutlineGrey);
  EXPECT_EQ(px(x0 + 31, y0 + 16), px(x0 + 16, y0 + 16));
  EXPECT_NE(px(x0 + 16, y0 + 16)[0], OutlineGrey);
  // The legend's bar ends: the colours of 0 % and 10 % daylight factor.
  const auto lo = viridis(0), hi = viridis(1);
  EXPECT_EQ(px(layout.bar_x, layout.bar_y + 2), (std::array<std::uint8_t, 4>{lo[0], lo[1], lo[2], 255}));
  EXPECT_EQ(px(layout.bar_x + layout.bar_width - 1, layout.bar_y + 2),
            (std::array<std::uint8_t, 4>{hi[0], hi[1], hi[2], 255}));
}

TEST(ResultImages, RotatedLShapedGridKeepsOnePixelPerSensorAndTransparentHoles) {
  // A 0.4 m lattice rotated by 30 degrees with a 3 x 3 corner cut out (an L-shaped room).
  const double a = deg_to_rad(30.0);
  const Vec3 u{std::cos(a) * 0.4, std::sin(a) * 0.4, 0}, v{-std::sin(a) * 0.4, std::cos(a) * 0.4, 0};
  std::vector<SensorPoint> sensors;
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 9; ++i)
      if (!(i >= 6 && j >= 4)) sensors.push_back({Vec3{10, 20, 0.85} + u * i + v * j, {0, 0, 1}});
  const std::string results = test::empty_dir("report_images_rotated"), dir = results + "/grid";
  write_grid_folder(dir, sensors);
  const GridResult grid = grid_model("grid", sensors);
  write_grid_images(results, CaseResult{}, grid);
  const SensorLattice& lattice = grid.lattice;
  ASSERT_TRUE(lattice.regular);
  EXPECT_EQ(lattice.columns * lattice.rows, 63);
  expect_exr_equals_csv(dir, grid, sensors.size(), true);
}

TEST(ResultImages, PointsOffALatticeGiveOneRowInSensorOrder) {
  std::vector<SensorPoint> sensors{{{0, 0, 0.8}, {0, 0, 1}}, {{1, 0.3, 0.8}, {0, 0, 1}}, {{2.7, 1.1, 0.8}, {0, 0, 1}}};
  EXPECT_FALSE(sensor_lattice(sensors).regular);
  sensors = {{{0, 0, 0.8}, {0, 0, 1}}, {{1, 0, 0.8}, {0, 0, 1}}, {{0, 1, 1.8}, {0, 0, 1}}};  // not on one plane
  EXPECT_FALSE(sensor_lattice(sensors).regular);
  sensors = {{{0, 0, 0.8}, {0, 0, 1}}, {{1, 0, 0.8}, {0, 0, 1}}, {{2.5, 0, 0.8}, {0, 0, 1}}, {{4, 3, 0.8}, {0, 0, 1}}};
  const std::string results = test::empty_dir("report_images_points"), dir = results + "/grid";
  write_grid_folder(dir, sensors);
  const GridResult grid = grid_model("grid", sensors);
  write_grid_images(results, CaseResult{}, grid);
  const Exr exr = read_with_openexr(dir + "/daylight_factor.exr");
  EXPECT_EQ(exr.width, 4);
  EXPECT_EQ(exr.height, 1);
  EXPECT_EQ(exr.header.typedAttribute<Imf::StringAttribute>("dayphoton:layout").value(), "sensor order");
  expect_exr_equals_csv(dir, grid, sensors.size(), false);
}

TEST(ResultImages, MalformedTablesAreLocatedErrors) {
  const std::string results = test::empty_dir("report_images_malformed"), dir = results + "/grid";
  const std::vector<SensorPoint> sensors{{{0, 0, 0.8}, {0, 0, 1}}, {{1, 0, 0.8}, {0, 0, 1}}};
  write_grid_folder(dir, sensors);
  std::ofstream(dir + "/daylight_factor.csv") << "index,x,y,z,df_percent\n0,0,0,0.8,1.5\n1,1,0,0.8,abc\n";
  const GridResult grid = grid_model("grid", sensors);
  try {
    write_grid_images(results, CaseResult{}, grid);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("daylight_factor.csv:3:"), std::string::npos) << e.what();
  }
}

TEST(ResultImages, SkyFisheyeGeometryAndMean) {
  // Bin b has radiance (b, 2b, 3b) in column 0 and (3b, 6b, 9b) in column 1: the mean is (2b, 4b, 6b).
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  RadianceMatrix m(static_cast<std::size_t>(basis.bin_count()), 2, 3);
  for (int b = 0; b < basis.bin_count(); ++b)
    for (int c = 0; c < 3; ++c) {
      m.at(static_cast<std::size_t>(b), 0, c) = static_cast<float>(b * (c + 1));
      m.at(static_cast<std::size_t>(b), 1, c) = static_cast<float>(3 * b * (c + 1));
    }
  const int size = 200;
  const FloatImage one = sky_fisheye(m, 0, basis, size);
  const FloatImage mean = sky_fisheye(m, -1, basis, size);
  auto bin_at = [&](const FloatImage& im, int x, int y) { return im.at(0, x, y); };
  // Centre: the zenith cap (bin 145). Just inside the top edge: the horizon row's north patch
  // (bin 1). Left edge middle: the horizon toward the east (azimuth 90 deg = the border of
  // patches 8 and 9 (12 deg wide, centred on multiples of 12): a pixel a little north of it
  // sees patch 8 (84 deg); right edge: west (270 deg: patch 23, centred on 276 deg, spans
  // [270, 282); a pixel a little north of it is in it).
  EXPECT_EQ(bin_at(one, 100, 100), 145.0f);
  EXPECT_EQ(bin_at(one, 100, 1), 1.0f);
  EXPECT_EQ(bin_at(one, 1, 97), 8.0f);
  EXPECT_EQ(bin_at(one, 198, 97), 24.0f);
  EXPECT_EQ(one.at(3, 0, 0), 0.0f);  // corner: outside the circle
  EXPECT_EQ(one.at(3, 100, 100), 1.0f);
  // Every pixel inside the circle: the mean image is twice column 0, per channel.
  for (int y = 0; y < size; y += 7)
    for (int x = 0; x < size; x += 7)
      for (std::size_t c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(mean.at(c, x, y), 2.0f * one.at(c, x, y));
  EXPECT_THROW(sky_fisheye(m, 2, basis, size), std::invalid_argument);
  EXPECT_THROW(sky_fisheye(m, 0, sky::PatchBasis::reinhart(2), size), std::invalid_argument);
}

TEST(ResultImages, ToneMapIsMonotoneAndHandlesBadPixels) {
  FloatImage rgb(4, 1, {"R", "G", "B"});
  const float values[4] = {0.0f, 1.0f, 10.0f, std::nanf("")};
  for (int x = 0; x < 4; ++x)
    for (std::size_t c = 0; c < 3; ++c) rgb.at(c, x, 0) = values[x];
  const RgbaImage out = tone_map(rgb);
  EXPECT_EQ(out.at(0, 0)[1], 0);           // black stays black
  EXPECT_LT(out.at(1, 0)[1], out.at(2, 0)[1]);  // brighter stays brighter
  EXPECT_EQ(out.at(2, 0)[1], 255);         // the white point maps to white
  EXPECT_EQ(out.at(3, 0)[1], 0);           // NaN shown black
  EXPECT_EQ(out.at(3, 0)[3], 255);
}

TEST(ResultImages, PngRoundTripsThroughLibpng) {
  RgbaImage image(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      image.at(x, y) = {static_cast<std::uint8_t>(40 * x), static_cast<std::uint8_t>(100 * y), 7, static_cast<std::uint8_t>(255 - x)};
  int w = 0, h = 0;
  const std::vector<std::uint8_t> pixels = decode_png(encode_png(image), w, h);
  ASSERT_EQ(w, 3);
  ASSERT_EQ(h, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(pixels[static_cast<std::size_t>((y * 3 + x) * 4 + c)], image.at(x, y)[static_cast<std::size_t>(c)]);
  EXPECT_EQ(base64("Man"), "TWFu");
  EXPECT_EQ(base64("Ma"), "TWE=");
  EXPECT_EQ(base64("M"), "TQ==");
}

TEST(ColourScale, ViridisEndsTicksAndClamping) {
  EXPECT_EQ(hex_colour(viridis(0)), "#440154");
  EXPECT_EQ(hex_colour(viridis(1)), "#fde725");
  EXPECT_EQ(hex_colour(viridis(0.5)), "#21918c");
  const ColourScale df = daylight_factor_scale();
  EXPECT_EQ(df.position(-1), 0);
  EXPECT_EQ(df.position(25), 1);
  EXPECT_DOUBLE_EQ(df.position(5), 0.5);
  EXPECT_EQ(df.ticks(), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  const ColourScale lux = illuminance_scale();
  EXPECT_DOUBLE_EQ(lux.position(100), 1.0 / 3.0);
  EXPECT_EQ(lux.ticks(), (std::vector<double>{10, 100, 1000, 10000}));
}

TEST(YearHour, ParsesAndRejects) {
  const YearHour h = parse_year_hour("12/21/9.5");
  EXPECT_EQ(h.month, 12);
  EXPECT_EQ(h.day, 21);
  EXPECT_EQ(h.hour, 9.5);
  for (const char* bad : {"", "6/21", "13/1/12", "6/0/12", "6/21/0", "6/21/25", "6-21-12", "6/21/12x"})
    EXPECT_THROW(parse_year_hour(bad), std::invalid_argument) << bad;
}
