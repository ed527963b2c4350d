// Test support: a RADIANCE scene of polygons rewritten in another length unit (every polygon
// vertex divided by the unit's metres), as an exporter working in feet, inches or millimetres
// would write it. Comments are dropped; other primitives are copied as they are (the scenes
// converted hold polygons and materials without lengths).
#pragma once

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace dayphoton::test {

inline std::string radiance_in_units(const std::string& metric_text, double metres_per_unit) {
  std::istringstream lines(metric_text);
  std::string words, line;
  while (std::getline(lines, line)) {
    const std::size_t hash = line.find('#');
    words += (hash == std::string::npos ? line : line.substr(0, hash)) + "\n";
  }
  std::istringstream in(words);
  std::vector<std::string> t;
  for (std::string w; in >> w;) t.push_back(w);
  std::string out;
  auto put = [&](const std::string& w, const char* sep) { out += w + sep; };
  for (std::size_t i = 0; i + 2 < t.size();) {
    const bool polygon = t[i + 1] == "polygon";
    put(t[i], " "), put(t[i + 1], " "), put(t[i + 2], "\n");
    i += 3;
    for (int list = 0; list < 3; ++list) {
      const std::size_t n = std::stoul(t[i]);
      put(t[i++], n == 0 ? "\n" : " ");
      for (std::size_t k = 0; k < n; ++k, ++i) {
        if (polygon && list == 2) {
          char buf[40];
          std::snprintf(buf, sizeof buf, "%.17g", std::stod(t[i]) / metres_per_unit);
          put(buf, k + 1 == n ? "\n" : " ");
        } else {
          put(t[i], k + 1 == n ? "\n" : " ");
        }
      }
    }
    out += "\n";
  }
  return out;
}

}  // namespace dayphoton::test
