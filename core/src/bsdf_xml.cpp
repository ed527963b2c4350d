// BSDF XML reader: see bsdf_xml.h. The file is parsed with pugixml (Debian libpugixml-dev;
// docs/architecture.md says why), whose nodes carry their byte offset in the file
// (xml_node::offset_debug); offsets become 1-based line:column here, and a value inside
// ScatteringData is located by its own offset within the element's text (the text is parsed
// without end-of-line normalisation, so its offsets are the file's).
#include "dayphoton/core/bsdf_xml.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <pugixml.hpp>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/sha256.h"
#include "dayphoton/core/shirley_chiu.h"
#include "dayphoton/core/tensor_tree.h"
#include "dayphoton/core/units.h"

namespace dayphoton {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string trimmed(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

// Element name without a namespace prefix ("bsdf:Layer" -> "Layer").
std::string_view local_name(const pugi::xml_node& node) {
  std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

pugi::xml_node child(const pugi::xml_node& node, std::string_view name) {
  for (pugi::xml_node c : node.children())
    if (c.type() == pugi::node_element && local_name(c) == name) return c;
  return {};
}

std::vector<pugi::xml_node> children(const pugi::xml_node& node, std::string_view name) {
  std::vector<pugi::xml_node> out;
  for (pugi::xml_node c : node.children())
    if (c.type() == pugi::node_element && local_name(c) == name) out.push_back(c);
  return out;
}

class Reader {
 public:
  Reader(std::string shown_as, std::string text) : m_shown(std::move(shown_as)), m_text(std::move(text)) {
    m_line_starts.push_back(0);
    for (std::size_t i = 0; i < m_text.size(); ++i)
      if (m_text[i] == '\n') m_line_starts.push_back(i + 1);
  }

  SourceLocation at_offset(std::ptrdiff_t offset) const {
    SourceLocation loc;
    loc.file = m_shown;
    if (offset < 0) return loc;
    const auto it = std::upper_bound(m_line_starts.begin(), m_line_starts.end(), static_cast<std::size_t>(offset));
    const std::size_t line = static_cast<std::size_t>(it - m_line_starts.begin());
    loc.line = static_cast<int>(line);
    loc.column = static_cast<int>(static_cast<std::size_t>(offset) - m_line_starts[line - 1]) + 1;
    return loc;
  }
  std::string line_text(int line) const {
    if (line < 1 || static_cast<std::size_t>(line) > m_line_starts.size()) return {};
    const std::size_t a = m_line_starts[static_cast<std::size_t>(line - 1)];
    std::size_t b = m_text.find('\n', a);
    if (b == std::string::npos) b = m_text.size();
    if (b > a && m_text[b - 1] == '\r') --b;
    return m_text.substr(a, b - a);
  }
  // An element's location: offset_debug points at its name; step back to the '<'.
  SourceLocation at(const pugi::xml_node& node) const {
    std::ptrdiff_t offset = node.offset_debug();
    if (node.type() == pugi::node_element && offset > 0 && m_text[static_cast<std::size_t>(offset - 1)] == '<') --offset;
    return at_offset(offset);
  }
  void error(const SourceLocation& loc, std::string message) {
    m_diagnostics.error(loc, std::move(message), line_text(loc.line));
  }
  void error(const pugi::xml_node& node, std::string message) { error(at(node), std::move(message)); }
  [[noreturn]] void fail(const pugi::xml_node& node, std::string message) {
    error(node, std::move(message));
    m_diagnostics.throw_if_errors();
    throw std::logic_error("unreachable");
  }

  const std::string& text() const { return m_text; }
  Diagnostics& diagnostics() { return m_diagnostics; }

  // The text of a required child element, trimmed; a located error if it is missing.
  std::string required_text(const pugi::xml_node& parent, std::string_view name) {
    const pugi::xml_node c = child(parent, name);
    if (!c) fail(parent, "<" + std::string(local_name(parent)) + "> has no <" + std::string(name) + ">");
    return trimmed(c.child_value());
  }
  double required_number(const pugi::xml_node& parent, std::string_view name) {
    const pugi::xml_node c = child(parent, name);
    if (!c) fail(parent, "<" + std::string(local_name(parent)) + "> has no <" + std::string(name) + ">");
    const std::string s = trimmed(c.child_value());
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      fail(c, "<" + std::string(name) + "> '" + s + "' is not a number");
    return v;
  }

 private:
  std::string m_shown;
  std::string m_text;
  std::vector<std::size_t> m_line_starts;
  Diagnostics m_diagnostics;
};

KlemsBasis read_basis(Reader& r, const pugi::xml_node& basis) {
  std::vector<KlemsRing> rings;
  const std::vector<pugi::xml_node> blocks = children(basis, "AngleBasisBlock");
  if (blocks.empty()) r.fail(basis, "<AngleBasis> has no <AngleBasisBlock>");
  int patches = 0;
  for (const pugi::xml_node& block : blocks) {
    const pugi::xml_node bounds = child(block, "ThetaBounds");
    if (!bounds) r.fail(block, "<AngleBasisBlock> has no <ThetaBounds>");
    const double lower = r.required_number(bounds, "LowerTheta");
    const double upper = r.required_number(bounds, "UpperTheta");
    const double phis = r.required_number(block, "nPhis");
    if (!(phis >= 1 && phis <= MaxKlemsPatches && phis == std::floor(phis)))
      r.fail(child(block, "nPhis"), "<nPhis> must be a whole number from 1 to " + std::to_string(MaxKlemsPatches));
    patches += static_cast<int>(phis);
    if (patches > MaxKlemsPatches)
      r.fail(block, "the angle basis has more than " + std::to_string(MaxKlemsPatches) + " patches");
    rings.push_back({deg_to_rad(lower), deg_to_rad(upper), static_cast<int>(phis)});
  }
  try {
    return KlemsBasis(std::move(rings));
  } catch (const std::invalid_argument& e) {
    r.fail(basis, std::string("angle basis: ") + e.what());
  }
}

struct Block {
  pugi::xml_node element, data;
  std::vector<double> values;  ///< [incoming * n + outgoing]
};

// The numbers of a ScatteringData element, each located if it is not a non-negative finite
// number; `values` is filled in [incoming * n + outgoing] order.
void read_values(Reader& r, const pugi::xml_node& data, int n, bool rows_are_incoming, std::vector<double>& values) {
  const pugi::xml_node text_node = data.first_child();
  const std::size_t expected = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (!text_node || (text_node.type() != pugi::node_pcdata && text_node.type() != pugi::node_cdata)) {
    r.error(data, "<ScatteringData> holds no values (" + std::to_string(expected) + " expected: " +
                      std::to_string(n) + " x " + std::to_string(n) + ")");
    return;
  }
  const std::string_view text = text_node.value();
  const std::ptrdiff_t base = text_node.offset_debug();
  auto separator = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; };
  // Count first, so that a short text claiming a large basis allocates nothing.
  std::size_t count = 0;
  for (std::size_t i = 0; i < text.size();) {
    while (i < text.size() && separator(text[i])) ++i;
    if (i >= text.size()) break;
    ++count;
    while (i < text.size() && !separator(text[i])) ++i;
  }
  if (count != expected) {
    r.error(data, "<ScatteringData> holds " + std::to_string(count) + " values, not " + std::to_string(expected) +
                      " (" + std::to_string(n) + " x " + std::to_string(n) + " for the angle basis' " +
                      std::to_string(n) + " patches)");
    return;
  }
  values.assign(expected, 0.0);
  count = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && separator(text[i])) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && !separator(text[j])) ++j;
    const std::string token(text.substr(i, j - i));
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(token.c_str(), &end);
    const SourceLocation loc = r.at_offset(base + static_cast<std::ptrdiff_t>(i));
    if (*end != '\0' || token.empty())
      r.error(loc, "BSDF value '" + token.substr(0, 40) + "' is not a number");
    else if (!std::isfinite(v) || errno == ERANGE)
      r.error(loc, "BSDF value '" + token.substr(0, 40) + "' is not finite");
    else if (v < 0)
      r.error(loc, "BSDF value " + token.substr(0, 40) + " is negative (a BSDF is >= 0)");
    const std::size_t row = count / static_cast<std::size_t>(n), column = count % static_cast<std::size_t>(n);
    const std::size_t incoming = rows_are_incoming ? row : column, outgoing = rows_are_incoming ? column : row;
    values[incoming * static_cast<std::size_t>(n) + outgoing] = v;
    ++count;
    i = j;
    if (r.diagnostics().at_cap()) return;
  }
}

const char* const DirectionNames[] = {"Transmission Front", "Transmission Back", "Reflection Front",
                                      "Reflection Back"};

// The index in DirectionNames of a <WavelengthDataBlock>'s direction, recorded in `found`; -1
// (after a located error) for an unknown direction or a second block of one.
int block_direction(Reader& r, const pugi::xml_node& block, pugi::xml_node found[4]) {
  const std::string direction = r.required_text(block, "WavelengthDataDirection");
  int k = -1;
  for (int d = 0; d < 4; ++d)
    if (lower(direction) == lower(DirectionNames[d])) k = d;
  if (k < 0) {
    r.error(child(block, "WavelengthDataDirection"),
            "unknown <WavelengthDataDirection> '" + direction +
                "' (expected Transmission Front, Transmission Back, Reflection Front or Reflection Back)");
    return -1;
  }
  if (found[k]) {
    r.error(block, "a second '" + std::string(DirectionNames[k]) + "' block (the first is at line " +
                       std::to_string(r.at(found[k]).line) + ")");
    return -1;
  }
  found[k] = block;
  return k;
}

// The projection of a tensor tree onto the Klems Full basis (klems_bsdf_data.h): incoming
// patch i at its centre direction; each slice cell split into n x n sub-squares, n =
// ceil(ProjectionSplit size) (none wider than 1/ProjectionSplit), each sub-square's share
// f pi s^2 given to the Klems patch of its centre. Energy is kept exactly per incoming patch
// (sum_j f(i, j) Lambda_j is the slice's T or R); which outgoing patch gets a sub-square
// straddling a patch edge is decided by its centre.
constexpr double ProjectionSplit = 64;
void project_on_klems(const TensorTreeBsdfData& tt, KlemsBsdfData& d) {
  d.basis = KlemsBasis::full();
  const int n = d.basis.size();
  const std::size_t nn = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<double>* matrices[] = {&d.transmission_front, &d.transmission_back, &d.reflection_front,
                                     &d.reflection_back};
  for (auto* m : matrices) m->assign(nn, 0.0);
  constexpr double Pi = 3.14159265358979323846;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < n; ++i) {
      const double theta = d.basis.centre_theta_rad(i), phi = d.basis.centre_phi_rad(i);
      const Vec3 in{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                    (side == 0 ? 1.0 : -1.0) * std::cos(theta)};
      const TensorTreeBsdfData::Slice& s = tt.slices[side][static_cast<std::size_t>(tt.slice_of(side, in))];
      for (std::size_t c = 0; c < s.cells.size(); ++c) {
        const TensorTreeBsdfData::Cell& cell = s.cells[c];
        const bool transmitted = c < s.transmitted;
        std::vector<double>& m = *matrices[(transmitted ? 0 : 2) + side];
        const int split = std::max(1, static_cast<int>(std::ceil(ProjectionSplit * cell.size)));
        const double step = static_cast<double>(cell.size) / split;
        const double weight = static_cast<double>(cell.value) * Pi * step * step;
        if (weight == 0) continue;
        for (int a = 0; a < split; ++a)
          for (int b = 0; b < split; ++b) {
            const Vec3 out = tt.outgoing_direction(in, cell.u + (a + 0.5) * step,
                                                                    cell.v + (b + 0.5) * step, 1.0);
            m[static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(d.basis.patch(out))] +=
                weight;
          }
      }
    }
  for (auto* m : matrices)
    for (std::size_t k = 0; k < nn; ++k) (*m)[k] /= d.basis.projected_solid_angle(static_cast<int>(k % static_cast<std::size_t>(n)));
}

// A TensorTree3 or TensorTree4 layer (tensor_tree_bsdf_data.h; docs/materials.md
// "Tensor-tree BSDF").
std::shared_ptr<const KlemsBsdfData> read_tensor_tree(Reader& r, const pugi::xml_node& layer, const std::string& shown_as,
                                                      int ndim) {
  auto tt = std::make_shared<TensorTreeBsdfData>();
  tt->ndim = ndim;
  pugi::xml_node found[4];
  bool any_visible = false;
  // RADIANCE's bsdf2ttree writes each block in a Visible <WavelengthData> of its own.
  for (const pugi::xml_node& wavelength : children(layer, "WavelengthData")) {
    if (lower(r.required_text(wavelength, "Wavelength")) != "visible") continue;  // Solar, NIR, CIE-X/Z
    any_visible = true;
    for (const pugi::xml_node& block : children(wavelength, "WavelengthDataBlock")) {
      const int k = block_direction(r, block, found);
      if (k < 0) continue;
      const pugi::xml_node basis = child(block, "AngleBasis");
      if (!basis) r.fail(block, "<WavelengthDataBlock> of a tensor tree has no <AngleBasis> (LBNL/Shirley-Chiu)");
      if (lower(trimmed(basis.child_value())) != "lbnl/shirley-chiu")
        r.fail(basis, "unknown tensor-tree angle basis '" + trimmed(basis.child_value()) +
                          "' (a tensor-tree block has 'LBNL/Shirley-Chiu')");
      // <ScatteringDataType> is not checked: bsdf2ttree writes BTDF on reflection blocks too,
      // and RADIANCE's bsdf_t.c does not read it.
      const pugi::xml_node scattering = child(block, "ScatteringData");
      if (!scattering) r.fail(block, "<WavelengthDataBlock> has no <ScatteringData>");
      const pugi::xml_node text_node = scattering.first_child();
      if (!text_node || (text_node.type() != pugi::node_pcdata && text_node.type() != pugi::node_cdata))
        r.fail(scattering, "<ScatteringData> holds no tensor tree");
      try {
        tt->trees[k] = parse_tensor_tree(text_node.value(), ndim);
      } catch (const TensorTreeError& e) {
        r.error(r.at_offset(text_node.offset_debug() + static_cast<std::ptrdiff_t>(e.offset)),
                std::string(DirectionNames[k]) + ": " + e.message);
      }
    }
  }
  if (!any_visible) r.fail(layer, "<Layer> has no Visible <WavelengthData> (dayphoton uses the visible BSDF)");
  for (int k = 0; k < 4; ++k)
    if (!found[k]) r.error(layer, "the Visible data has no '" + std::string(DirectionNames[k]) + "' block");
  r.diagnostics().throw_if_errors();
  const std::size_t cells = tt->slice_cell_count();
  if (cells > MaxTensorTreeSliceCells)
    r.fail(layer, "the tensor trees need " + std::to_string(cells) + " cells of outgoing directions over their " +
                      "incidences, more than the " + std::to_string(MaxTensorTreeSliceCells) + " allowed");
  tt->build_slices();
  // Energy: per incident cell and side, T + R <= 1 + tolerance (the worst cell per side).
  for (int side = 0; side < 2; ++side) {
    const std::vector<TensorTreeBsdfData::Slice>& slices = tt->slices[side];
    std::size_t worst = slices.size();
    int over = 0;
    for (std::size_t k = 0; k < slices.size(); ++k)
      if (slices[k].albedo > 1.0 + BsdfAlbedoTolerance) {
        ++over;
        if (worst == slices.size() || slices[k].albedo > slices[worst].albedo) worst = k;
      }
    if (worst < slices.size()) {
      double incident[2] = {0, 0};
      tt->slice_incident(side, static_cast<int>(worst), incident);
      std::ostringstream msg;
      msg << (side == 0 ? "front" : "back") << " incidence at theta ";
      if (ndim == 3) {
        msg << format_number(rad_to_deg(std::asin(std::min(1.0, 1.0 - 2.0 * incident[0]))));
      } else {
        double x = 0, y = 0;
        shirley_chiu_square_to_disc(incident[0], incident[1], x, y);
        msg << format_number(rad_to_deg(std::asin(std::min(1.0, std::hypot(x, y))))) << ", phi "
            << format_number(rad_to_deg(std::atan2(y, x)));
      }
      msg << " degrees (incident cell " << worst + 1 << " of " << slices.size()
          << "): hemispherical T + R = " << format_number(slices[worst].albedo) << " (T "
          << format_number(slices[worst].transmittance) << ", R "
          << format_number(slices[worst].albedo - slices[worst].transmittance) << ") exceeds 1 + "
          << format_number(BsdfAlbedoTolerance);
      if (over > 1) msg << "; " << over - 1 << " more incident cells exceed it too";
      r.error(child(found[side], "ScatteringData"), msg.str());
    }
  }
  r.diagnostics().throw_if_errors();
  auto data = std::make_shared<KlemsBsdfData>();
  data->file = shown_as;
  data->content_sha256 = sha256_hex(r.text());
  data->device_type = trimmed(child(child(layer, "Material"), "DeviceType").child_value());
  project_on_klems(*tt, *data);
  data->tensor_tree = std::move(tt);
  return data;
}

}  // namespace

std::shared_ptr<const KlemsBsdfData> read_bsdf_xml(const std::string& path, const std::string& shown_as,
                                                   const SourceLocation& referenced_from) {
  std::uint64_t size = 0;
  std::ifstream in = open_input_file(path, "BSDF file", referenced_from);
  if (input_file_size(path, size) && size > MaxBsdfFileBytes)
    throw InputError(referenced_from, "BSDF file '" + shown_as + "' is " + std::to_string(size) +
                                          " bytes, more than the " + std::to_string(MaxBsdfFileBytes) +
                                          " a BSDF file may have");
  return read_bsdf_xml_text(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
                            shown_as);
}

std::shared_ptr<const KlemsBsdfData> read_bsdf_xml_text(std::string text, const std::string& shown_as) {
  Reader r(shown_as, std::move(text));

  pugi::xml_document doc;
  // No end-of-line normalisation, so offsets inside text are the file's (see the top).
  const unsigned options = pugi::parse_default & ~pugi::parse_eol;
  const pugi::xml_parse_result parsed = doc.load_buffer(r.text().data(), r.text().size(), options);
  if (!parsed) {
    const SourceLocation loc = r.at_offset(parsed.offset);
    throw InputError(loc, std::string("not well-formed XML: ") + parsed.description(), r.line_text(loc.line));
  }
  const pugi::xml_node root = doc.document_element();
  if (!root) throw InputError(r.at_offset(0), "no XML element (an LBNL WINDOW / IGSDB BSDF file has <WindowElement>)");
  if (local_name(root) != "WindowElement")
    r.fail(root, "the root element is <" + std::string(local_name(root)) +
                     ">, not <WindowElement> (an LBNL WINDOW / IGSDB BSDF file)");
  const pugi::xml_node optical = child(root, "Optical");
  if (!optical) r.fail(root, "<WindowElement> has no <Optical>");
  const std::vector<pugi::xml_node> layers = children(optical, "Layer");
  if (layers.empty()) r.fail(optical, "<Optical> has no <Layer>");
  if (layers.size() > 1)
    r.fail(layers[1], "<Optical> has " + std::to_string(layers.size()) + " layers; one (the system's) is supported");
  const pugi::xml_node layer = layers[0];
  const pugi::xml_node definition = child(layer, "DataDefinition");
  if (!definition) r.fail(layer, "<Layer> has no <DataDefinition>");

  const pugi::xml_node structure = child(definition, "IncidentDataStructure");
  if (!structure) r.fail(definition, "<DataDefinition> has no <IncidentDataStructure>");
  const std::string layout = lower(trimmed(structure.child_value()));
  bool rows_are_incoming = false;
  if (layout == "columns")
    rows_are_incoming = false;
  else if (layout == "rows")
    rows_are_incoming = true;
  else if (layout == "tensortree3" || layout == "tensortree4")
    return read_tensor_tree(r, layer, shown_as, layout == "tensortree3" ? 3 : 4);
  else
    r.fail(structure, "<IncidentDataStructure> '" + trimmed(structure.child_value()) +
                          "' is not 'Columns', 'Rows', 'TensorTree3' or 'TensorTree4'");

  std::map<std::string, std::pair<KlemsBasis, pugi::xml_node>> bases;
  for (const pugi::xml_node& basis : children(definition, "AngleBasis")) {
    const std::string name = r.required_text(basis, "AngleBasisName");
    bases.emplace(lower(name), std::make_pair(read_basis(r, basis), basis));
  }
  if (bases.empty()) r.fail(definition, "<DataDefinition> defines no <AngleBasis>");

  auto data = std::make_shared<KlemsBsdfData>();
  data->file = shown_as;
  data->content_sha256 = sha256_hex(r.text());
  data->device_type = trimmed(child(child(layer, "Material"), "DeviceType").child_value());
  std::vector<double>* matrices[] = {&data->transmission_front, &data->transmission_back, &data->reflection_front,
                                     &data->reflection_back};
  pugi::xml_node found[4];
  pugi::xml_node visible;
  const KlemsBasis* basis_used = nullptr;
  for (const pugi::xml_node& wavelength : children(layer, "WavelengthData")) {
    if (lower(r.required_text(wavelength, "Wavelength")) != "visible") continue;  // Solar, NIR, CIE-X/Z
    if (visible) r.fail(wavelength, "a second Visible <WavelengthData> (the first is at line " +
                                        std::to_string(r.at(visible).line) + ")");
    visible = wavelength;
    for (const pugi::xml_node& block : children(wavelength, "WavelengthDataBlock")) {
      const int k = block_direction(r, block, found);
      if (k < 0) continue;
      const std::string column_basis = r.required_text(block, "ColumnAngleBasis");
      const std::string row_basis = r.required_text(block, "RowAngleBasis");
      const auto column_it = bases.find(lower(column_basis));
      if (column_it == bases.end()) r.fail(child(block, "ColumnAngleBasis"), "undefined angle basis '" + column_basis + "'");
      const auto row_it = bases.find(lower(row_basis));
      if (row_it == bases.end()) r.fail(child(block, "RowAngleBasis"), "undefined angle basis '" + row_basis + "'");
      if (!(column_it->second.first == row_it->second.first))
        r.fail(block, "rows and columns on different angle bases ('" + row_basis + "', '" + column_basis +
                          "') are not supported");
      if (basis_used && !(*basis_used == column_it->second.first))
        r.fail(block, "the blocks use different angle bases; one basis for all four is supported");
      basis_used = &column_it->second.first;
      const std::string type = lower(r.required_text(block, "ScatteringDataType"));
      const bool transmission = k < 2;
      if (type != (transmission ? "btdf" : "brdf"))
        r.error(child(block, "ScatteringDataType"),
                "<ScatteringDataType> '" + r.required_text(block, "ScatteringDataType") + "' for '" +
                    DirectionNames[k] + "' (expected " + (transmission ? "BTDF" : "BRDF") + ")");
      const pugi::xml_node scattering = child(block, "ScatteringData");
      if (!scattering) r.fail(block, "<WavelengthDataBlock> has no <ScatteringData>");
      read_values(r, scattering, basis_used->size(), rows_are_incoming, *matrices[k]);
    }
  }
  if (!visible) r.fail(layer, "<Layer> has no Visible <WavelengthData> (dayphoton uses the visible BSDF)");
  for (int k = 0; k < 4; ++k)
    if (!found[k]) r.error(visible, "the Visible data has no '" + std::string(DirectionNames[k]) + "' block");
  r.diagnostics().throw_if_errors();
  data->basis = *basis_used;

  // Energy: per incoming patch and side, T + R <= 1 + tolerance (one error per side: the
  // worst patch, and how many others exceed it too).
  const int n = data->basis.size();
  for (int side = 0; side < 2; ++side) {
    const std::vector<double>& t = side == 0 ? data->transmission_front : data->transmission_back;
    const std::vector<double>& rf = side == 0 ? data->reflection_front : data->reflection_back;
    int worst = -1, over = 0;
    double worst_total = 0, worst_t = 0, worst_r = 0;
    for (int i = 0; i < n; ++i) {
      const double tt = data->hemispherical(t, i), rr = data->hemispherical(rf, i);
      if (tt + rr > 1.0 + BsdfAlbedoTolerance) {
        ++over;
        if (tt + rr > worst_total) {
          worst = i;
          worst_total = tt + rr;
          worst_t = tt;
          worst_r = rr;
        }
      }
    }
    if (worst >= 0) {
      std::ostringstream msg;
      msg << (side == 0 ? "front" : "back") << " incidence, incoming patch " << worst + 1 << " (theta "
          << format_number(rad_to_deg(data->basis.centre_theta_rad(worst))) << ", phi "
          << format_number(rad_to_deg(data->basis.centre_phi_rad(worst)))
          << " degrees): hemispherical T + R = " << format_number(worst_total) << " (T " << format_number(worst_t)
          << ", R " << format_number(worst_r) << ") exceeds 1 + " << format_number(BsdfAlbedoTolerance);
      if (over > 1) msg << "; " << over - 1 << " more incoming patches exceed it too";
      r.error(child(found[side == 0 ? 0 : 1], "ScatteringData"), msg.str());
    }
  }
  r.diagnostics().throw_if_errors();
  return data;
}

}  // namespace dayphoton
