// Which of a case's materials stand for operable shading: a blind, a shade or a screen drawn
// as a material (a measured `bsdf`, a `translucent`) rather than generated as a `blinds`
// system. IES LM-83-12, "Approved Method: IES Spatial Daylight Autonomy (sDA) and Annual
// Sunlight Exposure (ASE)", section 2.2.6, takes ASE with every operable shading device
// retracted and sDA with the blinds operated hour by hour; a case that has such a material in
// place every hour gets neither verdict (study/compliance_verdicts.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "dayphoton/core/scene_description.h"

namespace dayphoton::study {

/// Whether an LBNL WINDOW / IGSDB BSDF file's <DeviceType> names a shading device: a blind,
/// shade, screen, shutter, louvre, drape, curtain or awning, in any case ("Venetian blind",
/// "Woven Shade", "Perforated Screen", "Roller shade"). A glazing system's ("Integral", "Other",
/// none) does not.
bool names_shading_device(std::string_view device_type);

/// Why LM-83 takes `material` as operable shading, in words for a verdict's reason, or nothing:
/// `shading: operable`; or, `shading` unstated, a `bsdf` whose file's DeviceType names a
/// shading device. `shading: fixed`, and every other material, give nothing.
std::optional<std::string> operable_shading_reason(const MaterialSpec& material);

}  // namespace dayphoton::study
