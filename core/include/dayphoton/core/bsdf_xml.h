// BSDF XML: reads an LBNL WINDOW / IGSDB / RADIANCE BSDF file (WindowElement / Optical / Layer, with
// DataDefinition/AngleBasis and WavelengthData blocks) into KlemsBsdfData
// (core/klems_bsdf_data.h). docs/materials.md "Measured BSDF (Klems)" describes what is read:
//   - one Layer; IncidentDataStructure "Columns" (each line of ScatteringData one outgoing
//     patch, WINDOW's layout) or "Rows" (each line one incoming patch);
//   - the AngleBasis named by each block's ColumnAngleBasis and RowAngleBasis (the same for
//     both), its rings from the file itself (ThetaBounds, nPhis), checked contiguous 0-90;
//   - the Visible WavelengthData: Transmission Front/Back and Reflection Front/Back, all four
//     required; other wavelengths (Solar, NIR, CIE-X/Z) are skipped;
//   - IncidentDataStructure TensorTree3 / TensorTree4 (isotropic / anisotropic tensor trees,
//     LBNL/Shirley-Chiu basis): read into the same struct with `tensor_tree` set
//     (klems_bsdf_data.h, tensor_tree_bsdf_data.h; docs/materials.md "Tensor-tree BSDF").
// Every error is located at file:line:column of the element or of the very value at fault:
// a value count that is not size x size, a value that is not a number, negative or not
// finite, and an incoming patch whose hemispherical T + R exceeds 1 + BsdfAlbedoTolerance.
#pragma once

#include <memory>
#include <string>

#include "dayphoton/core/klems_bsdf_data.h"
#include "dayphoton/core/source_location.h"

namespace dayphoton {

/// Largest BSDF file read (a Klems full file with solar and visible data is ~2 MB).
constexpr std::uint64_t MaxBsdfFileBytes = 256ULL << 20;
/// Most patches an angle basis may have (the Klems full basis has 145).
constexpr int MaxKlemsPatches = 1024;

/// Read `path` (opened as given). `shown_as` is the name errors print (the path as written
/// in the project); `referenced_from` locates "file not found". Throws InputError.
std::shared_ptr<const KlemsBsdfData> read_bsdf_xml(const std::string& path, const std::string& shown_as,
                                                   const SourceLocation& referenced_from);

/// The same from the file's text (the fuzz harness; errors name `shown_as`).
std::shared_ptr<const KlemsBsdfData> read_bsdf_xml_text(std::string text, const std::string& shown_as);

}  // namespace dayphoton
