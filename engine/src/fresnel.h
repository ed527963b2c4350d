// Fresnel reflectance of a smooth interface between two dielectrics, for s- and
// p-polarised light separately and unpolarised (their mean).
//
// Why both polarisations: thin glass (thin_glass_fresnel.h) sums the internal reflections of
// each polarisation separately before averaging, as RADIANCE's glass does; the dielectric
// interface (prisms) uses the unpolarised mean. Formulas: Born & Wolf, "Principles of
// Optics", section 1.5.2 (Fresnel equations), checked against the digest of seeds 002-004,
// section 4 checks #3-#5 (R(0) for n = 1.5 / 1.52 / 1.7; n = 1.5 at 45 deg).
#pragma once

namespace dayphoton::engine {

/// Reflectances of one interface at one angle. Transmittance is 1 - reflectance (no loss at
/// the interface itself).
struct FresnelReflectance {
  double s = 0;  ///< perpendicular (TE) polarisation
  double p = 0;  ///< parallel (TM) polarisation
  double unpolarised() const { return 0.5 * (s + p); }
};

/// Cosine of the refraction angle for light arriving with cosine `cos_incident_in` (>= 0)
/// on an interface with relative index `relative_index` = n_transmitted / n_incident.
/// Returns a negative value on total internal reflection.
double refracted_cosine(double cos_incident_in, double relative_index);

/// Fresnel reflectances for light arriving with cosine `cos_incident_in` (in [0, 1]) at an
/// interface with relative index n_transmitted / n_incident. Total internal reflection gives
/// s = p = 1.
FresnelReflectance fresnel_dielectric(double cos_incident_in, double relative_index);
/// The same with the refracted cosine already known: `cos_transmitted` must be
/// refracted_cosine(cos_incident_in, relative_index) (one square root fewer on a path that
/// needs both, e.g. the thin-pane series at every port passage; identical results).
FresnelReflectance fresnel_dielectric(double cos_incident_in, double relative_index, double cos_transmitted);

}  // namespace dayphoton::engine
