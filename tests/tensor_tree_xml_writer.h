// Test helper: the text of a TensorTree3 (or TensorTree4) BSDF XML file (the layout of RADIANCE's bsdf2ttree
// output: DataDefinition/IncidentDataStructure, one Visible WavelengthData, each block's
// <AngleBasis>LBNL/Shirley-Chiu</AngleBasis> and its tree in <ScatteringData>), from the four
// trees' texts, and a leaf grid sampling a function of the tree's coordinates (u0, u1, u2)
// (core/tensor_tree_bsdf_data.h) at cell centres. Used to write BSDFs of known models.
#pragma once

#include <array>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>

namespace dayphoton::test {

/// A single leaf of 2^(3 log2) values: f at the centre of each cell, dimension 0 slowest.
inline std::string tensor_tree_leaf(int log2, const std::function<double(double, double, double)>& f) {
  const int n = 1 << log2;
  std::ostringstream x;
  x << "{\n";
  char buf[32];
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      for (int c = 0; c < n; ++c) {
        std::snprintf(buf, sizeof buf, "%.9g ", f((a + 0.5) / n, (b + 0.5) / n, (c + 0.5) / n));
        x << buf;
      }
      x << "\n";
    }
  x << "}";
  return x.str();
}

/// A single TensorTree4 leaf of 2^(4 log2) values: f at the centre of each cell.
inline std::string tensor_tree_leaf4(int log2, const std::function<double(double, double, double, double)>& f) {
  const int n = 1 << log2;
  std::ostringstream x;
  x << "{\n";
  char buf[32];
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c) {
        for (int d = 0; d < n; ++d) {
          std::snprintf(buf, sizeof buf, "%.9g ", f((a + 0.5) / n, (b + 0.5) / n, (c + 0.5) / n, (d + 0.5) / n));
          x << buf;
        }
        x << "\n";
      }
  x << "}";
  return x.str();
}

/// Trees in KlemsBsdfData's order: Transmission Front, Transmission Back, Reflection Front,
/// Reflection Back. An empty text leaves that block out.
inline std::string tensor_tree_xml(const std::array<std::string, 4>& trees,
                                   const std::string& basis = "LBNL/Shirley-Chiu",
                                   const std::string& structure = "TensorTree3") {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<WindowElement xmlns=\"http://windows.lbl.gov\">\n<WindowElementType>System</WindowElementType>\n"
    << "<Optical>\n<Layer>\n<Material><Name>test</Name><DeviceType>Other</DeviceType></Material>\n"
    << "<DataDefinition>\n<IncidentDataStructure>" << structure << "</IncidentDataStructure>\n</DataDefinition>\n"
    << "<WavelengthData>\n<LayerNumber>System</LayerNumber>\n<Wavelength unit=\"Integral\">Visible</Wavelength>\n";
  const char* names[] = {"Transmission Front", "Transmission Back", "Reflection Front", "Reflection Back"};
  for (int k = 0; k < 4; ++k) {
    if (trees[static_cast<std::size_t>(k)].empty()) continue;
    x << "<WavelengthDataBlock>\n<WavelengthDataDirection>" << names[k] << "</WavelengthDataDirection>\n<AngleBasis>"
      << basis << "</AngleBasis>\n<ScatteringDataType>" << (k < 2 ? "BTDF" : "BRDF")
      << "</ScatteringDataType>\n<ScatteringData>\n"
      << trees[static_cast<std::size_t>(k)] << "\n</ScatteringData>\n</WavelengthDataBlock>\n";
  }
  x << "</WavelengthData>\n</Layer>\n</Optical>\n</WindowElement>\n";
  return x.str();
}

}  // namespace dayphoton::test
