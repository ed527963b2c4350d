// RADIANCE scene reader: see radiance_scene.h (syntax, what is read and refused) and
// docs/radiance-import.md. Source of the syntax and of every primitive's arguments: G. Ward,
// "The RADIANCE 5.x Synthetic Imaging System" (reference manual), sections "Scene
// Description", "Surfaces", "Materials", "Auxiliary"; of the xform options: the xform(1)
// manual page of RADIANCE.
#include "dayphoton/project/radiance_scene.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/radiance_material.h"

namespace dayphoton::project {
namespace {

namespace fs = std::filesystem;
using Role = RadianceModifierRole;

// ---- affine transforms (xform) -----------------------------------------------------------
struct Affine {
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  // linear part
  Vec3 translate{0, 0, 0};
  double scale = 1;  // uniform scale (rotations keep lengths)

  Vec3 apply(const Vec3& p) const {
    return Vec3{dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)} + translate;
  }
  /// This transform followed by `next`: linear part next.L * L, translation next(t).
  Affine then(const Affine& next) const {
    Affine r;
    for (std::size_t i = 0; i < 3; ++i)
      r.rows[i] = rows[0] * next.rows[i].x + rows[1] * next.rows[i].y + rows[2] * next.rows[i].z;
    r.translate = next.apply(translate);
    r.scale = scale * next.scale;
    return r;
  }
  static Affine rotation(int axis, double degrees) {
    const double a = deg_to_rad(degrees), c = std::cos(a), s = std::sin(a);
    Affine r;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // right-handed about `axis`
    r.rows[i][i] = c;
    r.rows[i][j] = -s;
    r.rows[j][i] = s;
    r.rows[j][j] = c;
    return r;
  }
};

// ---- tokens ---------------------------------------------------------------------------------
struct Token {
  std::string text;
  SourceLocation location;
};

/// A cursor over one file's text that knows line and column (1-based).
class Scanner {
 public:
  Scanner(const std::string& text, const std::string& path) : m_text(text), m_path(path) {}

  void skip_space() {
    while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) advance();
  }
  bool at_end() const { return m_pos >= m_text.size(); }
  char peek() const { return m_text[m_pos]; }
  SourceLocation here() const { return {m_path, m_line, m_column}; }

  /// The rest of the line from the cursor (a trailing backslash continues it, as RADIANCE's
  /// command lines do), consumed.
  std::string rest_of_line() {
    std::string out;
    while (m_pos < m_text.size() && m_text[m_pos] != '\n') {
      if (m_text[m_pos] == '\\' && m_pos + 1 < m_text.size() && m_text[m_pos + 1] == '\n') {
        advance();
        advance();
        out += ' ';
        continue;
      }
      out += m_text[m_pos];
      advance();
    }
    return out;
  }

  /// The next word (white space separated; a double-quoted word may hold spaces), or false
  /// at the end of the text.
  bool word(Token& token) {
    skip_space();
    if (at_end()) return false;
    token.location = here();
    token.text.clear();
    if (peek() == '"') {
      advance();
      while (!at_end() && peek() != '"') {
        token.text += peek();
        advance();
      }
      if (!at_end()) advance();
      return true;
    }
    while (!at_end() && !std::isspace(static_cast<unsigned char>(peek()))) {
      token.text += peek();
      advance();
    }
    return true;
  }

  /// Line `line` of the text, for the caret of a message.
  std::string line_text(int line) const {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
      start = m_text.find('\n', start);
      if (start == std::string::npos) return {};
      ++start;
    }
    std::size_t end = m_text.find('\n', start);
    std::string s = m_text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
  }

 private:
  void advance() {
    if (m_text[m_pos] == '\n') {
      ++m_line;
      m_column = 1;
    } else {
      ++m_column;
    }
    ++m_pos;
  }
  const std::string& m_text;
  std::string m_path;
  std::size_t m_pos = 0;
  int m_line = 1, m_column = 1;
};

bool parse_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

bool parse_count(const std::string& text, long long& out) {
  if (text.empty() || text.size() > 9) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  out = std::atoll(text.c_str());
  return true;
}

const std::vector<std::string> SurfaceTypes = {"polygon", "ring", "cylinder", "tube", "cone", "cup",
                                               "sphere", "bubble", "source", "mesh", "instance"};

// ---- the modifiers defined so far -----------------------------------------------------------
struct Modifier {
  std::string type;
  Role role = Role::Invalid;
  int material = -1;               ///< Material: index into RadianceScene::materials
  std::string material_modifier;   ///< the RADIANCE name of that material
  std::string reason;              ///< Unsupported
  std::string through;             ///< how surfaces reach the material ("illum 'x' shows its alternate ...")
  SourceLocation location;
  bool reported = false;           ///< Unsupported: reported at its first use
  int skipped = 0;                 ///< surfaces left out because of it
  std::shared_ptr<const MaterialSpec> bsdf;  ///< a BSDF / aBSDF modifier's material (file read)
};

bool same_material(const MaterialSpec& a, const MaterialSpec& b) {
  const engine::BsdfMaterialParameters *bsdf_a = engine::bsdf_parameters(a), *bsdf_b = engine::bsdf_parameters(b);
  if (bsdf_a || bsdf_b)
    return bsdf_a && bsdf_b && bsdf_a->data->content_sha256 == bsdf_b->data->content_sha256 && bsdf_a->up == bsdf_b->up;
  return a.type == b.type && a.reflectance == b.reflectance && a.specularity == b.specularity &&
         a.roughness == b.roughness && a.transmittance == b.transmittance &&
         a.refractive_index == b.refractive_index && a.transmissivity == b.transmissivity &&
         a.transmitted_specular == b.transmitted_specular && a.type_as_written == b.type_as_written;
}

std::string located_at(const SourceLocation& loc) { return loc.to_string(); }

// ---- tessellation ----------------------------------------------------------------------------
/// Two unit vectors u, v with u x v = n (n unit).
void frame_of(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  u = normalize(cross(helper, n));
  v = cross(n, u);
}

class Reader {
 public:
  Reader(const RadianceSceneOptions& options, Diagnostics& diag) : m_options(options), m_diag(diag) {
    // The scene's unit: the transform every file is read under, before any !xform of its own.
    for (std::size_t k = 0; k < 3; ++k) m_transform.rows[k][static_cast<int>(k)] = options.metres_per_unit;
    m_transform.scale = options.metres_per_unit;
  }

  void read_file(const std::string& path, const SourceLocation& referenced_from) {
    const std::string problem = input_file_problem(path);
    if (!problem.empty()) {
      error_at(referenced_from, "RADIANCE scene file '" + path + "' " + problem, {});
      return;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error_at(referenced_from, "cannot open RADIANCE scene file '" + path + "'", {});
      return;
    }
    std::ostringstream text;
    text << in.rdbuf();
    read_text(text.str(), path);
  }

  void read_text(const std::string& text, const std::string& path) {
    if (static_cast<int>(m_files.size()) >= RadianceMaxXformDepth) return;
    if (m_files.empty() && m_first_file.file.empty()) m_first_file = SourceLocation{path, 0, 0};
    m_files.push_back(path);
    Scanner s(text, path);
    m_scanners.push_back(&s);
    while (!m_diag.at_cap()) {
      s.skip_space();
      if (s.at_end()) break;
      if (s.peek() == '#') {
        (void)s.rest_of_line();
        continue;
      }
      if (s.peek() == '!') {
        const SourceLocation at = s.here();
        command(s.rest_of_line().substr(1), at, path);
        continue;
      }
      if (!primitive(s)) break;  // a syntax error: the rest of this file cannot be trusted
    }
    m_scanners.pop_back();
    m_files.pop_back();
  }

  RadianceScene finish() {
    for (const auto& [name, m] : m_modifiers_by_first_definition) {
      (void)name;
      if (m.skipped == 0) continue;
      if (m.role == Role::LightSource)
        warning_at(m.location, m.type + " '" + name + "' is a light source: " + std::to_string(m.skipped) +
                                   " surface" + (m.skipped == 1 ? "" : "s") +
                                   " using it left out (dayphoton's sources are the sky and the sun)");
      else if (m.role == Role::Unsupported)
        warning_at(m.location, m.type + " '" + name + "': " + std::to_string(m.skipped) + " surface" +
                                   (m.skipped == 1 ? "" : "s") + " using it left out (unsupported: skip)");
    }
    if (m_void_skipped > 0)
      warning_at(m_first_void, std::to_string(m_void_skipped) + " surface" + (m_void_skipped == 1 ? "" : "s") +
                                   " with modifier 'void' left out (RADIANCE traces straight through them)");
    if (m_sources_skipped > 0)
      warning_at(m_first_source, std::to_string(m_sources_skipped) + " distant 'source' primitive" +
                                     (m_sources_skipped == 1 ? "" : "s") +
                                     " left out (dayphoton's sources are the sky and the sun)");
    if (m_warnings > RadianceMaxWarnings)
      m_diag.warning(m_first_file, std::to_string(m_warnings - RadianceMaxWarnings) +
                                       " more warning(s) of this RADIANCE scene not shown");
    return std::move(m_scene);
  }

 private:
  // ---- messages ----------------------------------------------------------------------------
  std::string line_of(const SourceLocation& loc) const {
    for (std::size_t i = m_files.size(); i-- > 0;)
      if (loc.file == m_files[i]) return m_scanners[i]->line_text(loc.line);
    return loc.known() ? read_source_line(loc.file, loc.line) : std::string();
  }
  void error_at(const SourceLocation& loc, const std::string& message, const std::string& line) {
    m_diag.error(loc, message, line);
  }
  void error(const SourceLocation& loc, const std::string& message) { m_diag.error(loc, message, line_of(loc)); }
  void warning_at(const SourceLocation& loc, const std::string& message) {
    if (++m_warnings > RadianceMaxWarnings) return;
    m_diag.warning(loc, message, line_of(loc));
  }
  /// Unsupported input: an error, or with `unsupported: skip` a warning.
  void unsupported(const SourceLocation& loc, const std::string& message) {
    if (m_options.skip_unsupported)
      warning_at(loc, message + " (skipped: unsupported: skip)");
    else
      error(loc, message + " (or set 'unsupported: skip' to leave such surfaces out)");
  }

  // ---- commands ----------------------------------------------------------------------------
  void command(const std::string& line, const SourceLocation& at, const std::string& path) {
    std::istringstream words(line);
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    const std::string expand_hint =
        "; dayphoton never runs commands: run it yourself and read its output file instead, or expand "
        "every command of the file with 'xform -e " + fs::path(path).filename().string() + " > expanded.rad'";
    if (args.empty() || args[0] != "xform") {
      error(at, "command '!" + (args.empty() ? std::string() : args[0]) + "': RADIANCE runs it in a shell" +
                    expand_hint);
      return;
    }
    for (const std::string& a : args)
      if (a.find_first_of("|;&<>`$'\"*?") != std::string::npos) {
        error(at, "'!xform' with shell syntax ('" + a + "') is not a plain xform" + expand_hint);
        return;
      }
    // Transforms apply in the order written; -i N repeats the group that follows it (up to
    // the next -i) N times (xform(1); RADIANCE's xf.c).
    Affine total, group;
    long long repeat = 1;
    auto close_group = [&]() {
      for (long long k = 0; k < repeat; ++k) total = total.then(group);
      group = Affine{};
    };
    std::vector<std::string> files;
    auto number = [&](std::size_t& i, double& out) {
      if (i + 1 >= args.size() || !parse_number(args[i + 1], out)) {
        error(at, "'!xform': option " + args[i] + " needs a number");
        return false;
      }
      ++i;
      return true;
    };
    for (std::size_t i = 1; i < args.size(); ++i) {
      const std::string& a = args[i];
      double x = 0, y = 0, z = 0;
      if (a == "-t") {
        if (!number(i, x) || !number(i, y) || !number(i, z)) return;
        Affine t;
        t.translate = Vec3{x, y, z};
        group = group.then(t);
      } else if (a == "-rx" || a == "-ry" || a == "-rz") {
        const int axis = a[2] - 'x';
        if (!number(i, x)) return;
        group = group.then(Affine::rotation(axis, x));
      } else if (a == "-s") {
        if (!number(i, x)) return;
        if (!(x > 0)) {
          error(at, "'!xform': scale " + format_number(x) + " must be positive");
          return;
        }
        Affine s;
        for (int k = 0; k < 3; ++k) s.rows[static_cast<std::size_t>(k)][k] = x;
        s.scale = x;
        group = group.then(s);
      } else if (a == "-i") {
        long long n = 0;
        if (i + 1 >= args.size() || !parse_count(args[i + 1], n) || n > RadianceMaxXformIterations) {
          error(at, "'!xform': option -i needs a count from 0 to " + std::to_string(RadianceMaxXformIterations));
          return;
        }
        ++i;
        close_group();
        repeat = n;
      } else if (a == "-n") {
        // -n NAME prefixes the identifiers xform writes (xform(1)): names, not geometry;
        // dayphoton's messages keep the identifiers of the file.
        if (i + 1 >= args.size() || args[i + 1].empty() || args[i + 1][0] == '-') {
          error(at, "'!xform': option -n needs a name");
          return;
        }
        ++i;
      } else if (!a.empty() && a[0] == '-') {
        error(at, "'!xform' option '" + a + "' is not read (only -t, -rx, -ry, -rz, -s, -i and -n)" + expand_hint);
        return;
      } else {
        files.push_back(a);
      }
    }
    close_group();
    if (files.empty()) {
      error(at, "'!xform' without a file would read its standard input" + expand_hint);
      return;
    }
    const fs::path folder = fs::path(path).parent_path();
    for (const std::string& f : files) {
      const std::string resolved =
          (fs::path(f).is_absolute() ? fs::path(f) : folder / f).lexically_normal().string();
      bool cycle = false;
      for (const std::string& open : m_files) {
        std::error_code ec;
        cycle = cycle || fs::equivalent(open, resolved, ec) || open == resolved;
      }
      if (cycle) {
        error(at, "'!xform' reads '" + f + "', which is already being read (a file that includes itself)");
        continue;
      }
      if (static_cast<int>(m_files.size()) >= RadianceMaxXformDepth) {
        error(at, "'!xform' nesting deeper than " + std::to_string(RadianceMaxXformDepth) + " files");
        continue;
      }
      const Affine saved = m_transform;
      m_transform = total.then(m_transform);
      read_file(resolved, at);
      m_transform = saved;
    }
  }

  // ---- primitives --------------------------------------------------------------------------
  /// Reads one primitive; false after a syntax error.
  bool primitive(Scanner& s) {
    Token modifier, type, id;
    if (!s.word(modifier)) return false;
    const std::string what_prefix = "primitive starting with '" + modifier.text + "'";
    if (!s.word(type) || !s.word(id)) {
      error(modifier.location, what_prefix + ": the file ends before its type and identifier");
      return false;
    }
    const std::string what = type.text + " '" + id.text + "'";
    if (type.text == "alias") {
      Token reference;
      if (!s.word(reference)) {
        error(type.location, what + ": the file ends before the name it aliases");
        return false;
      }
      define_alias(modifier, id, reference);
      return true;
    }
    std::vector<std::string> strings;
    std::size_t integers = 0;
    std::vector<double> reals;
    std::vector<SourceLocation> real_locations;
    for (int list = 0; list < 3; ++list) {
      static const char* const kinds[3] = {"string", "integer", "real"};
      Token count;
      long long n = 0;
      if (!s.word(count)) {
        error(id.location, what + ": the file ends before its " + kinds[list] + " arguments");
        return false;
      }
      if (!parse_count(count.text, n)) {
        error(count.location, what + ": expected the number of " + kinds[list] + " arguments, got '" +
                                  count.text + "'" +
                                  (count.text[0] == '#' ? " (RADIANCE reads comments only between primitives)" : ""));
        return false;
      }
      for (long long k = 0; k < n; ++k) {
        Token arg;
        if (!s.word(arg)) {
          error(count.location, what + ": the file ends after " + std::to_string(k) + " of its " +
                                    std::to_string(n) + " " + kinds[list] + " arguments");
          return false;
        }
        if (list == 0) strings.push_back(arg.text);
        if (list == 1) ++integers;
        if (list == 2) {
          double v = 0;
          if (!parse_number(arg.text, v)) {
            error(arg.location, what + ": real argument " + std::to_string(k + 1) + " '" + arg.text +
                                    "' is not a number" +
                                    (arg.text[0] == '#' ? " (RADIANCE reads comments only between primitives)" : ""));
            return false;
          }
          reals.push_back(v);
          real_locations.push_back(arg.location);
        }
      }
    }
    if (is_radiance_modifier_type(type.text) || type.text == "void") {
      define_modifier(modifier, type, id, reals, strings, integers);
    } else if (std::find(SurfaceTypes.begin(), SurfaceTypes.end(), type.text) != SurfaceTypes.end()) {
      surface(modifier, type, id, reals, strings, integers);
    } else {
      std::vector<std::string> known = SurfaceTypes;
      known.push_back("alias");
      const std::string hint = closest_match(type.text, known);
      error(type.location, "unknown RADIANCE primitive type '" + type.text + "' of '" + id.text + "'" +
                               (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
    }
    return true;
  }

  /// The modifier named `name` as the primitive at `at` uses it, or null after reporting.
  Modifier* find_modifier(const Token& name, const std::string& what) {
    const auto it = m_modifiers.find(name.text);
    if (it != m_modifiers.end()) return &it->second;
    std::vector<std::string> names;
    for (const auto& kv : m_modifiers) names.push_back(kv.first);
    const std::string hint = closest_match(name.text, names);
    error(name.location, what + ": modifier '" + name.text + "' is not defined before it is used" +
                             (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)") +
                             " (files are read in order, as oconv reads them)");
    return nullptr;
  }

  void store(const std::string& name, Modifier m) {
    m_modifiers[name] = m;
    if (!m_modifiers_by_first_definition.count(name)) m_modifiers_by_first_definition.emplace(name, m);
    m_scene.modifier_names.push_back(name);
  }
  /// Counts live in the first definition's record (reported once at the end).
  Modifier& tally(const std::string& name) {
    auto it = m_modifiers_by_first_definition.find(name);
    return it->second;
  }

  void define_alias(const Token& modifier, const Token& id, const Token& reference) {
    const std::string what = "alias '" + id.text + "'";
    const Modifier* target = find_modifier(reference, what);
    if (!target) return;
    Modifier m = *target;
    m.location = id.location;
    m.reported = false;
    m.skipped = 0;
    if (modifier.text != "void" && modifier.text != "inherit") {
      m.role = Role::Unsupported;
      m.type = "alias";
      m.reason = what + " puts modifier '" + modifier.text + "' on '" + reference.text +
                 "': patterns, textures and mixtures are not supported";
    }
    store(id.text, m);
  }

  /// A BSDF / aBSDF modifier's material: its file, relative to the folder of the file being
  /// read, read now (its errors located in the XML file, a missing file at the modifier's
  /// type), and its up vector turned by the xform of that file. False after an error.
  bool bsdf_material(const RadianceMaterialResult& r, const Token& type, const Token& id, Modifier& m) {
    const fs::path folder = m_files.empty() ? fs::path() : fs::path(m_files.back()).parent_path();
    const std::string resolved =
        (fs::path(r.bsdf_file).is_absolute() ? fs::path(r.bsdf_file) : folder / r.bsdf_file).lexically_normal().string();
    std::shared_ptr<const KlemsBsdfData> data;
    try {
      data = read_bsdf_xml(resolved, resolved, type.location);
    } catch (const InputError& e) {
      for (const Diagnostic& d : e.diagnostics()) {
        if (d.source_line.empty())
          error(d.location, d.message);  // at the modifier: its .rad line
        else
          m_diag.error(d.location, d.message, d.source_line);  // in the XML file
      }
      return false;
    }
    const Vec3 up = m_transform.apply(r.bsdf_up) - m_transform.translate;
    m.bsdf = std::make_shared<MaterialSpec>(engine::bsdf_material_spec(id.text, std::move(data), up));
    return true;
  }

  void define_modifier(const Token& modifier, const Token& type, const Token& id,
                       const std::vector<double>& reals, const std::vector<std::string>& strings,
                       std::size_t integers) {
    const RadianceMaterialResult r = radiance_material(type.text, id.text, reals, strings, integers);
    Modifier m;
    m.type = type.text;
    m.role = r.role;
    m.location = id.location;
    m.reason = r.reason;
    const std::string what = type.text + " '" + id.text + "'";
    if (r.role == Role::Invalid) {
      error(type.location, r.reason);
    } else {
      for (const std::string& note : r.notes) warning_at(type.location, note);
    }
    // A material modified by anything (a pattern, texture or mixture) is not uniform. Light
    // sources are left out whatever modifies them (a sky's glow under its brightfunc).
    if (modifier.text != "void" && (r.role == Role::Material || r.role == Role::Invisible)) {
      const Modifier* pattern = find_modifier(modifier, what);
      if (!pattern) {
        m.role = Role::Invalid;
      } else {
        m.role = Role::Unsupported;
        m.reason = what + " is modified by " + pattern->type + " '" + modifier.text +
                   "': patterns, textures and mixtures are not supported (dayphoton's materials are uniform)";
      }
    }
    if (m.role == Role::Material && !r.bsdf_file.empty() && !bsdf_material(r, type, id, m)) m.role = Role::Invalid;
    if (m.role == Role::Material) {
      // Lengths in the material (a dielectric's absorption) in metres: the scale the file is
      // read under, the scene's unit and any !xform -s, as xform itself rewrites them.
      MaterialSpec spec = m.bsdf ? *m.bsdf : radiance_material_in_metres(r.material, m_transform.scale);
      spec.location = id.location;
      m.material = add_material(spec);
      m.material_modifier = id.text;
    }
    if (r.role == Role::LightSource && !r.alternate_material.empty()) {
      // An illum shows its alternate material to every ray but a source sample.
      Token alternate{r.alternate_material, type.location};
      const Modifier* alt = find_modifier(alternate, what + "'s alternate material");
      if (alt) {
        const std::string light_type = m.type;
        m = *alt;
        m.type = light_type;
        m.location = id.location;
        m.reported = false;
        m.skipped = 0;
        m.through = what + " shows its alternate material '" + r.alternate_material + "'";
        if (alt->role == Role::Material)
          warning_at(type.location, what + ": its surfaces take its alternate material '" +
                                        r.alternate_material + "' (the illum's own emission is not a source here)");
      }
    }
    store(id.text, m);
  }

  int add_material(MaterialSpec spec) {
    std::vector<MaterialSpec>& materials = m_scene.materials;
    const std::string name = spec.name;
    for (std::size_t i = 0; i < materials.size(); ++i)
      if (materials[i].name == name) {
        if (same_material(materials[i], spec)) return static_cast<int>(i);
        spec.name = name + "@" + spec.location.to_string();
        break;
      }
    materials.push_back(std::move(spec));
    return static_cast<int>(materials.size()) - 1;
  }

  void surface(const Token& modifier, const Token& type, const Token& id, const std::vector<double>& reals,
               const std::vector<std::string>& strings, std::size_t integers) {
    const std::string what = type.text + " '" + id.text + "'";
    const SourceLocation& at = modifier.location;
    if (type.text == "source") {
      if (m_sources_skipped++ == 0) m_first_source = at;
      return;
    }
    if (type.text == "mesh" || type.text == "instance") {
      unsupported(at, what + ": " +
                          (type.text == "mesh"
                               ? std::string("compiled RADIANCE meshes (obj2mesh) are not read; give the OBJ "
                                             "file it was made from as a 'geometry.meshes' entry")
                               : std::string("octree instances are not read; read the scene files it was made "
                                             "from with '!xform'")));
      return;
    }
    if (!strings.empty() || integers != 0) {
      error(type.location, what + ": takes no string or integer arguments");
      return;
    }
    std::size_t expected = 0;
    if (type.text == "ring" || type.text == "cone" || type.text == "cup") expected = 8;
    if (type.text == "cylinder" || type.text == "tube") expected = 7;
    if (type.text == "sphere" || type.text == "bubble") expected = 4;
    if (type.text == "polygon") {
      if (reals.size() < 9 || reals.size() % 3 != 0) {
        error(type.location, what + ": needs 3 coordinates per vertex and at least 3 vertices (9 or more real "
                                    "arguments, a multiple of 3), got " + std::to_string(reals.size()));
        return;
      }
    } else if (reals.size() != expected) {
      error(type.location, what + ": takes " + std::to_string(expected) + " real arguments, got " +
                               std::to_string(reals.size()));
      return;
    }
    // Which material the surfaces take.
    int material = -1;
    std::string material_modifier;
    if (modifier.text == "void") {
      if (m_void_skipped++ == 0) m_first_void = at;
      return;
    }
    Modifier* m = find_modifier(modifier, what);
    if (!m) return;
    switch (m->role) {
      case Role::Material:
        material = m->material;
        material_modifier = m->material_modifier;
        break;
      case Role::Invisible:
        if (m_void_skipped++ == 0) m_first_void = at;
        return;
      case Role::LightSource:
        ++tally(modifier.text).skipped;
        return;
      case Role::Unsupported:
        if (!m->reported) {
          m->reported = true;
          unsupported(at, what + ": " + m->reason + " (defined at " + located_at(m->location) + ")");
        }
        if (m_options.skip_unsupported) ++tally(modifier.text).skipped;
        return;
      case Role::Invalid:
        return;  // reported at its definition
    }
    std::vector<std::vector<Vec3>> facets;
    bool solid = false;
    if (!tessellate(type, what, reals, facets, solid)) return;
    for (std::size_t k = 0; k < facets.size(); ++k) {
      RadianceSurface out;
      out.name = facets.size() == 1 ? id.text : id.text + "." + std::to_string(k);
      out.modifier = modifier.text;
      out.material_modifier = material_modifier;
      out.material = material;
      for (const Vec3& p : facets[k]) out.vertices.push_back(m_transform.apply(p));
      out.solid_face = solid;
      out.location = at;
      m_scene.surfaces.push_back(std::move(out));
    }
  }

  /// Segments per full circle of radius `radius_m` (before the transform). A sphere's facet
  /// departs from it along both its edges' directions, up to twice the sagitta: spheres ask
  /// with `doubly_curved`.
  int segments_for(double radius_m, const std::string& what, const SourceLocation& at,
                   bool doubly_curved = false) {
    const double scaled_m = radius_m * m_transform.scale;
    const double factor = doubly_curved ? 2.0 : 1.0;
    const int n = radiance_circle_segments(factor * scaled_m);
    const double sagitta_m = factor * scaled_m * (1 - std::cos(Pi / n));
    if (sagitta_m > RadianceTessellationTolerance_m * (1 + 1e-9))
      warning_at(at, what + ": radius " + format_number(scaled_m) + " m tessellated with " + std::to_string(n) +
                         " segments, up to " + format_number(sagitta_m) + " m from the true surface (above the " +
                         format_number(RadianceTessellationTolerance_m) + " m tolerance)");
    return n;
  }

  bool tessellate(const Token& type, const std::string& what, const std::vector<double>& a,
                  std::vector<std::vector<Vec3>>& facets, bool& solid) {
    const std::string& t = type.text;
    const SourceLocation& at = type.location;
    if (t == "polygon") {
      std::vector<Vec3> poly;
      for (std::size_t i = 0; i + 2 < a.size(); i += 3) poly.push_back(Vec3{a[i], a[i + 1], a[i + 2]});
      facets.push_back(std::move(poly));
      return true;
    }
    if (t == "sphere" || t == "bubble") {
      const Vec3 c{a[0], a[1], a[2]};
      const double r = a[3];
      if (!(r > 0)) {
        error(at, what + ": radius " + format_number(r) + " must be positive");
        return false;
      }
      const int n_lon = segments_for(r, what, at, /*doubly_curved=*/true);
      const int n_lat = std::max(2, n_lon / 2);
      auto point = [&](int j, int i) {
        const double theta = Pi * j / n_lat, phi = 2 * Pi * i / n_lon;
        if (j == 0) return c + Vec3{0, 0, r};
        if (j == n_lat) return c - Vec3{0, 0, r};
        return c + Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)} * r;
      };
      for (int j = 0; j < n_lat; ++j)
        for (int i = 0; i < n_lon; ++i) {
          std::vector<Vec3> f;
          // Outward: down the meridian, then east (see docs/radiance-import.md).
          if (j == 0) f = {point(0, 0), point(1, i), point(1, i + 1)};
          else if (j == n_lat - 1) f = {point(j, i), point(n_lat, 0), point(j, i + 1)};
          else f = {point(j, i), point(j + 1, i), point(j + 1, i + 1), point(j, i + 1)};
          if (t == "bubble") std::reverse(f.begin(), f.end());
          facets.push_back(std::move(f));
        }
      solid = t == "sphere";
      return true;
    }
    const Vec3 p0{a[0], a[1], a[2]};
    if (t == "ring") {
      const Vec3 dir{a[3], a[4], a[5]};
      double r0 = a[6], r1 = a[7];
      if (r0 > r1) std::swap(r0, r1);
      if (!(length(dir) > 0) || !(r0 >= 0) || !(r1 > r0)) {
        error(at, what + ": needs a non-zero normal and radii 0 <= r0 < r1");
        return false;
      }
      Vec3 u, v;
      const Vec3 n = normalize(dir);
      frame_of(n, u, v);
      const int segs = segments_for(r1, what, at);
      auto point = [&](double r, int i) {
        const double phi = 2 * Pi * i / segs;
        return p0 + (u * std::cos(phi) + v * std::sin(phi)) * r;
      };
      if (r0 == 0) {
        std::vector<Vec3> disc;
        for (int i = 0; i < segs; ++i) disc.push_back(point(r1, i));
        facets.push_back(std::move(disc));
      } else {
        for (int i = 0; i < segs; ++i) facets.push_back({point(r0, i), point(r1, i), point(r1, i + 1), point(r0, i + 1)});
      }
      return true;
    }
    // cylinder, tube (r0 = r1 = a[6]), cone, cup.
    const Vec3 p1{a[3], a[4], a[5]};
    const bool cyl = t == "cylinder" || t == "tube";
    const double r0 = a[6], r1 = cyl ? a[6] : a[7];
    const Vec3 axis = p1 - p0;
    if (!(length(axis) > 0) || !(r0 >= 0) || !(r1 >= 0) || !(r0 > 0 || r1 > 0)) {
      error(at, what + ": needs two different end points and radii >= 0, not both 0");
      return false;
    }
    Vec3 u, v;
    frame_of(normalize(axis), u, v);
    const int segs = segments_for(std::max(r0, r1), what, at);
    auto point = [&](const Vec3& base, double r, int i) {
      const double phi = 2 * Pi * i / segs;
      return base + (u * std::cos(phi) + v * std::sin(phi)) * r;
    };
    for (int i = 0; i < segs; ++i) {
      // Outward: along the circle at p0, then up the axis.
      std::vector<Vec3> f;
      if (r0 > 0) {
        f.push_back(point(p0, r0, i));
        f.push_back(point(p0, r0, i + 1));
      } else {
        f.push_back(p0);
      }
      if (r1 > 0) {
        f.push_back(point(p1, r1, i + 1));
        f.push_back(point(p1, r1, i));
      } else {
        f.push_back(p1);
      }
      if (t == "tube" || t == "cup") std::reverse(f.begin(), f.end());
      facets.push_back(std::move(f));
    }
    return true;
  }

  const RadianceSceneOptions& m_options;
  Diagnostics& m_diag;
  RadianceScene m_scene;
  std::map<std::string, Modifier> m_modifiers;  ///< the definition in effect, by name
  std::map<std::string, Modifier> m_modifiers_by_first_definition;
  std::vector<std::string> m_files;      ///< files being read (the xform nesting)
  std::vector<const Scanner*> m_scanners;
  Affine m_transform;                    ///< of the file being read
  int m_void_skipped = 0, m_sources_skipped = 0, m_warnings = 0;
  SourceLocation m_first_file;
  SourceLocation m_first_void, m_first_source;
};

}  // namespace

int radiance_circle_segments(double radius_m) {
  if (!(radius_m > RadianceTessellationTolerance_m)) return RadianceMinSegments;
  // Sagitta of a chord over angle 2 pi / n: r (1 - cos(pi / n)) <= tolerance.
  const double n = std::ceil(Pi / std::acos(1 - RadianceTessellationTolerance_m / radius_m));
  return static_cast<int>(std::clamp(n, double(RadianceMinSegments), double(RadianceMaxSegments)));
}

RadianceScene read_radiance_scene(const std::vector<std::string>& files, const RadianceSceneOptions& options,
                                  Diagnostics& diag, const std::vector<SourceLocation>& referenced_from) {
  Reader reader(options, diag);
  for (std::size_t i = 0; i < files.size(); ++i)
    reader.read_file(files[i], i < referenced_from.size() ? referenced_from[i] : SourceLocation{});
  return reader.finish();
}

RadianceScene read_radiance_scene_from_string(const std::string& text, const std::string& path,
                                              const RadianceSceneOptions& options, Diagnostics& diag) {
  Reader reader(options, diag);
  reader.read_text(text, path);
  return reader.finish();
}

}  // namespace dayphoton::project
