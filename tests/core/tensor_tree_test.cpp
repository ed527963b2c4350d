// Tensor trees (core/tensor_tree.h, the TensorTree3 path of core/bsdf_xml.h): the node and
// leaf order of RADIANCE's format (child n covers the upper half of dimension i where bit i
// of n is set; a leaf grid is row-major with dimension 0 slowest), the Shirley-Chiu mapping
// (area preserving, inverse of itself), a constant tree read as a Lambertian diffuser (its
// Klems projection the diffuser's matrix), and every malformed tree, bound or basis refused
// with an error at file:line:column.
#include "dayphoton/core/tensor_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "../tensor_tree_xml_writer.h"
#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/shirley_chiu.h"
#include "dayphoton/core/units.h"

using namespace dayphoton;

namespace {

std::string read_error(const std::string& text) {
  try {
    read_bsdf_xml_text(text, "tt.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Line and column (1-based) of the n-th occurrence (0-based) of `needle`.
std::string where(const std::string& text, const std::string& needle, int nth = 0) {
  std::size_t at = text.find(needle);
  for (int k = 0; k < nth && at != std::string::npos; ++k) at = text.find(needle, at + 1);
  if (at == std::string::npos) return "?";
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  return std::to_string(line) + ":" + std::to_string(at - line_start + 1);
}

const std::string Constant = "{ 0.1 }";

std::string four(const std::string& tf, const std::string& tb = Constant, const std::string& rf = Constant,
                 const std::string& rb = Constant) {
  return test::tensor_tree_xml({tf, tb, rf, rb});
}

}  // namespace

TEST(TensorTree, BranchAndLeafOrderAreRadiances) {
  // A branch of eight constant leaves: child n is the upper half of dimension i iff bit i.
  const TensorTree t = parse_tensor_tree("{ {0} {1}, {2} {3} {4} {5} {6} {7} }", 3);
  for (int n = 0; n < 8; ++n) {
    const double pos[3] = {(n & 1) ? 0.75 : 0.25, (n & 2) ? 0.6 : 0.1, (n & 4) ? 0.99 : 0.0};
    EXPECT_EQ(t.lookup(pos), static_cast<float>(n)) << n;
  }
  EXPECT_EQ(t.max_log2, 1);
  // One leaf of 2^(3*1) values: index = c0 * 4 + c1 * 2 + c2 (dimension 0 slowest).
  const TensorTree g = parse_tensor_tree("{ 0 1 2 3 4 5 6 7 }", 3);
  for (int n = 0; n < 8; ++n) {
    const double pos[3] = {(n & 4) ? 0.7 : 0.2, (n & 2) ? 0.7 : 0.2, (n & 1) ? 0.7 : 0.2};
    EXPECT_EQ(g.lookup(pos), static_cast<float>(n)) << n;
  }
  // The slice at u0 = 0.25 of the branch: the four children with bit 0 clear, tiling the square.
  double area = 0, weighted = 0;
  const double u0 = 0.25;
  t.for_each_slice_cell(&u0, [&](double, double, double s, float v) {
    area += s * s;
    weighted += v * s * s;
  });
  EXPECT_DOUBLE_EQ(area, 1.0);
  EXPECT_DOUBLE_EQ(weighted, (0 + 2 + 4 + 6) / 4.0);
  EXPECT_EQ(t.slice_cell_count(&u0), 4u);
}

TEST(TensorTree, ShirleyChiuPreservesAreaAndInvertsItself) {
  // Round trip, and the disc image of a square cell of side s has area pi s^2 (the cell's
  // projected solid angle): counted by a fine grid over the disc.
  for (double u : {0.01, 0.2, 0.5, 0.77, 0.99})
    for (double v : {0.03, 0.5, 0.61, 0.98}) {
      double x = 0, y = 0, u2 = 0, v2 = 0;
      shirley_chiu_square_to_disc(u, v, x, y);
      EXPECT_LE(x * x + y * y, 1.0 + 1e-12);
      shirley_chiu_disc_to_square(x, y, u2, v2);
      EXPECT_NEAR(u2, u, 1e-12);
      EXPECT_NEAR(v2, v, 1e-12);
    }
  const int n = 800;
  int inside = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -1 + 2 * (i + 0.5) / n, y = -1 + 2 * (j + 0.5) / n;
      if (x * x + y * y >= 1) continue;
      double u = 0, v = 0;
      shirley_chiu_disc_to_square(x, y, u, v);
      inside += u >= 0.5 && u < 0.625 && v >= 0.25 && v < 0.375;
    }
  const double area = inside * 4.0 / (n * n);
  // Grid counting error: the cell's boundary crosses ~ 4 * 0.125 * pi / (2/n) grid cells.
  EXPECT_NEAR(area, Pi * 0.125 * 0.125, 4 * 0.125 * Pi / (2.0 / n) * (4.0 / (n * n)));
}

TEST(TensorTree, ConstantTreeIsALambertianDiffuser) {
  // f = tau / pi everywhere: every slice transmits tau, and the Klems projection is the
  // Lambertian matrix tau / pi (each outgoing patch's integral over its Lambda).
  const auto d = read_bsdf_xml_text(four("{ 0.190985932 }", "{ 0.159154943 }", "{ 0.0795774715 }", "{ 0.0318309886 }"),
                                    "tt.xml");
  ASSERT_TRUE(d->tensor_tree);
  for (const auto& s : d->tensor_tree->slices[0]) {
    EXPECT_NEAR(s.transmittance, 0.6, 1e-7);
    EXPECT_NEAR(s.albedo, 0.85, 1e-7);
  }
  for (const auto& s : d->tensor_tree->slices[1]) EXPECT_NEAR(s.albedo, 0.6, 1e-7);
  for (int i = 0; i < d->basis.size(); i += 7) {
    EXPECT_NEAR(d->hemispherical(d->transmission_front, i), 0.6, 1e-6) << i;
    EXPECT_NEAR(d->hemispherical(d->reflection_back, i), 0.1, 1e-6) << i;
  }
  // Each matrix value: the 1/64 sub-squares whose centres fall in patch j carry its share,
  // so a value is tau / pi to within the sub-squares straddling the patch's edges: at most
  // 26 % for the smallest (horizon and cap) patches of this constant tree, exact on average.
  double weighted = 0;
  for (int j = 0; j < d->basis.size(); ++j) {
    EXPECT_NEAR(d->value(d->transmission_front, 0, j), 0.190985932, 0.26 * 0.190985932) << j;
    weighted += d->value(d->transmission_front, 0, j) * d->basis.projected_solid_angle(j);
  }
  EXPECT_NEAR(weighted, 0.6, 1e-6);
}

TEST(TensorTree, MalformedTreesAreLocated) {
  {  // wrong leaf count
    const std::string text = four("{ {1 2 3 4 5} {0} {0} {0} {0} {0} {0} {0} }");
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "{1 2 3") +
                                    ": error: Transmission Front: a tensor-tree leaf has 5 values; a leaf has 2^(3 k) values"),
              std::string::npos)
        << read_error(text);
  }
  {  // a branch with seven sub-trees
    const std::string text = four(Constant, "{ {0} {0} {0} {0} {0} {0} {0} }");
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "{ {0}") +
                                    ": error: Transmission Back: a branch of the tensor tree has 7 sub-trees, not 8"),
              std::string::npos)
        << read_error(text);
  }
  {  // depth over the bound: nine nested branches
    std::string deep = "{0}";
    for (int level = 0; level < MaxTensorTreeLog2 + 1; ++level) {
      std::string branch = "{";
      for (int c = 0; c < 8; ++c) branch += c == 0 ? deep : " {0}";
      deep = branch + "}";
    }
    const std::string text = four(Constant, Constant, deep);
    // The ninth '{' of the nest is the first too deep.
    const std::size_t block = text.find("Reflection Front");
    const std::size_t at = text.find(std::string(MaxTensorTreeLog2 + 1, '{'), block) + MaxTensorTreeLog2;
    const std::string e = read_error(text);
    EXPECT_NE(e.find("tt.xml:" + where(text.substr(0, at) + "\x01", "\x01") +
                     ": error: Reflection Front: the tensor tree is deeper than 8 levels"),
              std::string::npos)
        << e;
  }
  {  // a leaf too fine for its depth (k = 3 under 6 branch levels)
    std::string deep = test::tensor_tree_leaf(3, [](double, double, double) { return 0.1; });
    for (int level = 0; level < 6; ++level) {
      std::string branch = "{";
      for (int c = 0; c < 8; ++c) branch += c == 0 ? deep : " {0}";
      deep = branch + "}";
    }
    EXPECT_NE(read_error(four(deep)).find("the tensor tree is deeper than 8 levels"), std::string::npos);
  }
  {  // unknown basis
    std::string text = four(Constant);
    text.replace(text.find("LBNL/Shirley-Chiu", text.find("Reflection Back")), 17, "LBNL/Klems Full");
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "<AngleBasis>", 3) +
                                    ": error: unknown tensor-tree angle basis 'LBNL/Klems Full'"),
              std::string::npos)
        << read_error(text);
  }
  {  // a negative value, unbalanced braces, trailing characters
    const std::string neg = four("{ {0} {0} {0} {-0.5} {0} {0} {0} {0} }");
    EXPECT_NE(read_error(neg).find("tt.xml:" + where(neg, "-0.5") + ": error: Transmission Front: tensor-tree value -0.5 is negative"),
              std::string::npos)
        << read_error(neg);
    EXPECT_NE(read_error(four("{ {0} {0} ")).find("this '{' of the tensor tree is never closed"), std::string::npos);
    const std::string extra = four("{ 0.1 } 7");
    EXPECT_NE(read_error(extra).find("tt.xml:" + where(extra, "7\n") + ": error: Transmission Front: characters after"),
              std::string::npos)
        << read_error(extra);
  }
  {  // a missing block, as for a Klems file
    const std::string text = test::tensor_tree_xml({Constant, Constant, Constant, ""});
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "<Layer>") +
                                    ": error: the Visible data has no 'Reflection Back' block"),
              std::string::npos)
        << read_error(text);
  }
  {  // energy: T + R over 1 at every incidence of the front
    const std::string text = four("{ 0.3 }");  // T = 0.94, R = 0.31
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "<ScatteringData>") +
                                    ": error: front incidence at theta 30 degrees (incident cell 1 of 1): hemispherical T + R = 1.25"),
              std::string::npos)
        << read_error(text);
  }
  {  // TensorTree4: a leaf of 8 values (a TensorTree3 leaf) is a wrong count there
    const std::string text = test::tensor_tree_xml({"{ 0 1 2 3 4 5 6 7 }", Constant, Constant, Constant},
                                                   "LBNL/Shirley-Chiu", "TensorTree4");
    EXPECT_NE(read_error(text).find("tt.xml:" + where(text, "{ 0 1 2") +
                                    ": error: Transmission Front: a tensor-tree leaf has 8 values; a leaf has 2^(4 k) "
                                    "values (1, 16, 256 ...)"),
              std::string::npos)
        << read_error(text);
  }
}
