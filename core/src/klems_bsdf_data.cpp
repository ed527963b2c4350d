// KlemsBsdfData: see klems_bsdf_data.h.
#include "dayphoton/core/klems_bsdf_data.h"

namespace dayphoton {

double KlemsBsdfData::hemispherical(const std::vector<double>& matrix, int incoming) const {
  double sum = 0;
  for (int j = 0; j < basis.size(); ++j) sum += value(matrix, incoming, j) * basis.projected_solid_angle(j);
  return sum;
}

}  // namespace dayphoton
