// Test helper: KlemsBsdfData -> the text of an LBNL WINDOW BSDF XML file (Klems basis from the
// data, IncidentDataStructure Columns: each line of ScatteringData one OUTGOING patch, the
// values across it the incoming patches; WINDOW's layout). Used to write BSDFs of known
// models (clear glass, a Lambertian diffuser) that the reader and the engine must reproduce.
#pragma once

#include <cstdio>
#include <functional>
#include <sstream>
#include <string>

#include "dayphoton/core/klems_bsdf_data.h"
#include "dayphoton/core/units.h"

namespace dayphoton::test {

inline std::string bsdf_xml_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

inline std::string bsdf_xml(const KlemsBsdfData& d, const std::string& basis_name = "LBNL/Klems Full") {
  std::ostringstream x;
  const int n = d.basis.size();
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<WindowElement xmlns=\"http://windows.lbl.gov\">\n"
    << "  <WindowElementType>System</WindowElementType>\n"
    << "  <Optical>\n    <Layer>\n      <Material><Name>test</Name></Material>\n"
    << "      <DataDefinition>\n        <IncidentDataStructure>Columns</IncidentDataStructure>\n"
    << "        <AngleBasis>\n          <AngleBasisName>" << basis_name << "</AngleBasisName>\n";
  for (const KlemsRing& r : d.basis.rings()) {
    x << "          <AngleBasisBlock>\n            <Theta>"
      << bsdf_xml_number(r.lower_theta_rad == 0 ? 0 : rad_to_deg(0.5 * (r.lower_theta_rad + r.upper_theta_rad)))
      << "</Theta>\n            <nPhis>" << r.phi_count << "</nPhis>\n            <ThetaBounds><LowerTheta>"
      << bsdf_xml_number(rad_to_deg(r.lower_theta_rad)) << "</LowerTheta><UpperTheta>"
      << bsdf_xml_number(rad_to_deg(r.upper_theta_rad)) << "</UpperTheta></ThetaBounds>\n"
      << "          </AngleBasisBlock>\n";
  }
  x << "        </AngleBasis>\n      </DataDefinition>\n"
    << "      <WavelengthData>\n        <LayerNumber>System</LayerNumber>\n"
    << "        <Wavelength unit=\"Integral\">Visible</Wavelength>\n";
  const char* names[] = {"Transmission Front", "Transmission Back", "Reflection Front", "Reflection Back"};
  const std::vector<double>* m[] = {&d.transmission_front, &d.transmission_back, &d.reflection_front,
                                    &d.reflection_back};
  for (int k = 0; k < 4; ++k) {
    x << "        <WavelengthDataBlock>\n          <WavelengthDataDirection>" << names[k]
      << "</WavelengthDataDirection>\n          <ColumnAngleBasis>" << basis_name
      << "</ColumnAngleBasis>\n          <RowAngleBasis>" << basis_name
      << "</RowAngleBasis>\n          <ScatteringDataType>" << (k < 2 ? "BTDF" : "BRDF")
      << "</ScatteringDataType>\n          <ScatteringData>\n";
    for (int o = 0; o < n; ++o) {
      for (int i = 0; i < n; ++i) x << (i ? ", " : "") << bsdf_xml_number(d.value(*m[k], i, o));
      x << ",\n";
    }
    x << "          </ScatteringData>\n        </WavelengthDataBlock>\n";
  }
  x << "      </WavelengthData>\n    </Layer>\n  </Optical>\n</WindowElement>\n";
  return x.str();
}

/// A BSDF on `basis` from functions of (incoming patch, outgoing patch) giving f, 1/sr.
inline KlemsBsdfData klems_from(const KlemsBasis& basis, const std::function<double(int, int)>& tf,
                                const std::function<double(int, int)>& tb, const std::function<double(int, int)>& rf,
                                const std::function<double(int, int)>& rb) {
  KlemsBsdfData d;
  d.basis = basis;
  const int n = basis.size();
  for (auto* m : {&d.transmission_front, &d.transmission_back, &d.reflection_front, &d.reflection_back})
    m->assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i)
    for (int o = 0; o < n; ++o) {
      const std::size_t k = static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(o);
      d.transmission_front[k] = tf(i, o);
      d.transmission_back[k] = tb(i, o);
      d.reflection_front[k] = rf(i, o);
      d.reflection_back[k] = rb(i, o);
    }
  return d;
}

}  // namespace dayphoton::test
