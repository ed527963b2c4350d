// Wavefront OBJ reader (statement list and conventions in obj_reader.h).
// Reference: Wavefront Technologies, "Object Files (.obj)", Advanced Visualizer manual,
// Appendix B1 (vertex data v/vt/vn, the f element with v/vt/vn references and negative
// relative indices, usemtl grouping).
#include "dayphoton/project/obj_reader.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "dayphoton/core/error_text.h"
#include "dayphoton/core/input_file.h"
#include "text_tokens.h"

namespace dayphoton::project {

namespace {

using detail::NumberStatus;
using detail::Token;

/// Column just after the last token (where a missing value should have been).
int end_column(const std::vector<Token>& tokens) {
  return tokens.back().column + static_cast<int>(tokens.back().text.size());
}

// Statements that carry no surface geometry: skipped without comment.
const std::unordered_set<std::string>& ignored_statements() {
  static const std::unordered_set<std::string> s{
      "o", "g", "s", "mtllib", "l", "p", "vp", "mg", "lod", "bevel", "c_interp", "d_interp",
      "shadow_obj", "trace_obj", "usemap", "maplib", "call", "csh"};
  return s;
}

// Free-form geometry: rejected so that surfaces are never lost silently.
const std::unordered_set<std::string>& freeform_statements() {
  static const std::unordered_set<std::string> s{
      "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
      "trim",   "hole", "scrv", "sp",   "end",  "con",   "ctech", "stech"};
  return s;
}

class ObjParser {
 public:
  ObjParser(const std::string& path, Diagnostics& diag) : m_path(path), m_diag(diag) {}

  void parse(std::istream& in) {
    std::string line;
    int line_no = 0;
    const std::size_t errors_before = m_diag.error_count();
    bool any_valid = false;
    while (std::getline(in, line)) {
      ++line_no;
      if (!any_valid && m_diag.error_count() - errors_before >= detail::MaxErrorsBeforeValidLine) {
        m_diag.error({m_path, line_no, 0}, "stopping after " + std::to_string(detail::MaxErrorsBeforeValidLine) +
                                               " errors and no valid line: is this an OBJ file?");
        break;
      }
      const std::size_t errors_at_line = m_diag.error_count();
      parse_line(line, line_no);
      any_valid = any_valid || (m_diag.error_count() == errors_at_line && !detail::tokenize(line).empty());
      if (m_diag.at_cap()) break;  // enough to show; do not churn through a broken file
    }
  }

  ObjMesh take() {
    m_mesh.vertex_count = m_vertices.size();
    return std::move(m_mesh);
  }

 private:
  void error(const std::string& line, int line_no, int column, const std::string& message) {
    std::string shown = line;
    if (!shown.empty() && shown.back() == '\r') shown.pop_back();
    m_diag.error({m_path, line_no, column}, message, shown);
  }

  void parse_line(const std::string& line, int line_no) {
    const std::vector<Token> tokens = detail::tokenize(line);
    if (tokens.empty()) return;
    const std::string& keyword = tokens[0].text;
    if (keyword == "v") {
      parse_vertex(tokens, line, line_no);
    } else if (keyword == "vt" || keyword == "vn") {
      parse_attribute(tokens, line, line_no);
    } else if (keyword == "f" || keyword == "fo") {
      parse_face(tokens, line, line_no);
    } else if (keyword == "usemtl") {
      if (tokens.size() < 2) {
        error(line, line_no, end_column(tokens), "usemtl needs a material name");
        return;
      }
      // usemtl takes one material_name (Appendix B1; mtllib, by contrast, takes a list of
      // files). The MTL format says names "cannot include blanks", but exporters write them
      // ("usemtl Glass Pane"), so the rest of the line, up to a comment, is the one name, as
      // three.js, MeshLab and trimesh read it; runs of blanks inside it are kept as written.
      const Token& last = tokens.back();
      m_material = line.substr(static_cast<std::size_t>(tokens[1].column - 1),
                               static_cast<std::size_t>(last.column - tokens[1].column) + last.text.size());
      const bool seen = std::any_of(m_mesh.materials.begin(), m_mesh.materials.end(),
                                    [&](const ObjMaterialUse& m) { return m.name == m_material; });
      if (!seen) m_mesh.materials.push_back({m_material, {m_path, line_no, tokens[1].column}});
    } else if (ignored_statements().count(keyword)) {
      return;
    } else if (freeform_statements().count(keyword)) {
      error(line, line_no, tokens[0].column,
            "free-form geometry ('" + keyword + "') is not supported; export the mesh as polygons");
    } else {
      error(line, line_no, tokens[0].column, "unknown OBJ statement '" + detail::quoted_token(keyword) + "'");
    }
  }

  void parse_vertex(const std::vector<Token>& tokens, const std::string& line, int line_no) {
    const std::size_t n = tokens.size() - 1;
    Vec3 p;
    bool ok = true;
    for (std::size_t i = 1; i < tokens.size(); ++i) {
      double value = 0;
      const NumberStatus status = detail::parse_number(tokens[i].text, value);
      if (status == NumberStatus::NotANumber) {
        error(line, line_no, tokens[i].column, "expected a number, found '" + detail::quoted_token(tokens[i].text) + "'");
        ok = false;
      } else if (status == NumberStatus::NotFinite) {
        error(line, line_no, tokens[i].column, "vertex coordinate is not finite ('" + detail::quoted_token(tokens[i].text) + "')");
        ok = false;
      } else if (i <= 3) {
        p[static_cast<int>(i - 1)] = value;
      }
    }
    if (n != 3 && n != 4 && n != 6 && n != 7) {
      const int column = n < 3 ? end_column(tokens) : tokens[4].column;
      error(line, line_no, column,
            "a vertex needs x y z (optionally w, or r g b), found " + std::to_string(n) + " value(s)");
      ok = false;
    }
    // A bad vertex is still counted, so later indices keep their meaning; faces using it
    // are reported as such.
    m_vertices.push_back(p);
    m_vertex_ok.push_back(ok);
  }

  void parse_attribute(const std::vector<Token>& tokens, const std::string& line, int line_no) {
    const bool is_normal = tokens[0].text == "vn";
    for (std::size_t i = 1; i < tokens.size(); ++i) {
      double value = 0;
      if (detail::parse_number(tokens[i].text, value) != NumberStatus::Ok)
        error(line, line_no, tokens[i].column, "expected a finite number, found '" + detail::quoted_token(tokens[i].text) + "'");
    }
    const std::size_t n = tokens.size() - 1;
    if ((is_normal && n != 3) || (!is_normal && (n < 1 || n > 3)))
      error(line, line_no, tokens[0].column,
            std::string(is_normal ? "vn needs 3 components" : "vt needs 1 to 3 components") +
                ", found " + std::to_string(n));
    (is_normal ? m_normal_count : m_texcoord_count) += 1;
  }

  /// Resolve an OBJ index (1-based, or negative = relative) against `count` elements read
  /// so far; returns false with an error when it is 0 or out of range.
  bool resolve_index(const std::string& text, std::size_t count, const char* what,
                     const std::string& line, int line_no, int column, std::size_t& index) {
    long long value = 0;
    if (!detail::parse_integer(text, value)) {
      error(line, line_no, column, std::string("expected a ") + what + " index, found '" + detail::quoted_token(text) + "'");
      return false;
    }
    const long long n = static_cast<long long>(count);
    if (value == 0) {
      error(line, line_no, column, std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
      return false;
    }
    const long long resolved = value > 0 ? value - 1 : n + value;
    if (resolved < 0 || resolved >= n) {
      const std::string plural = std::string(what) == "vertex" ? "vertices" : std::string(what) + "s";
      error(line, line_no, column,
            std::string(what) + " index " + text + " is out of range (" + std::to_string(n) + " " +
                (n == 1 ? std::string(what) : plural) + " defined so far)");
      return false;
    }
    index = static_cast<std::size_t>(resolved);
    return true;
  }

  void parse_face(const std::vector<Token>& tokens, const std::string& line, int line_no) {
    ObjFace face;
    face.material = m_material;
    face.location = {m_path, line_no, tokens[0].column};
    bool ok = true;
    for (std::size_t t = 1; t < tokens.size(); ++t) {
      const Token& tok = tokens[t];
      // Split "v/vt/vn" keeping each part's column.
      std::vector<std::string> parts;
      std::vector<int> columns;
      std::size_t start = 0;
      while (true) {
        const std::size_t slash = tok.text.find('/', start);
        parts.push_back(tok.text.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
        columns.push_back(tok.column + static_cast<int>(start));
        if (slash == std::string::npos) break;
        start = slash + 1;
      }
      if (parts.size() > 3) {
        error(line, line_no, tok.column, "face vertex '" + detail::quoted_token(tok.text) + "' has more than v/vt/vn");
        ok = false;
        continue;
      }
      std::size_t vi = 0, other = 0;
      if (!resolve_index(parts[0], m_vertices.size(), "vertex", line, line_no, columns[0], vi)) {
        ok = false;
        continue;
      }
      if (parts.size() >= 2 && !parts[1].empty() &&
          !resolve_index(parts[1], m_texcoord_count, "texture coordinate", line, line_no, columns[1], other))
        ok = false;
      if (parts.size() == 3 &&
          !resolve_index(parts[2], m_normal_count, "normal", line, line_no, columns[2], other))
        ok = false;
      if (!m_vertex_ok[vi]) {
        error(line, line_no, tok.column, "face uses vertex " + parts[0] + ", which is invalid");
        ok = false;
        continue;
      }
      face.vertices.push_back(m_vertices[vi]);
    }
    if (tokens.size() - 1 < 3) {
      error(line, line_no, tokens[0].column,
            "a face needs at least 3 vertices, found " + std::to_string(tokens.size() - 1));
      ok = false;
    }
    if (ok) m_mesh.faces.push_back(std::move(face));
  }

  std::string m_path;
  Diagnostics& m_diag;
  ObjMesh m_mesh;
  std::vector<Vec3> m_vertices;
  std::vector<bool> m_vertex_ok;
  std::size_t m_texcoord_count = 0;
  std::size_t m_normal_count = 0;
  std::string m_material;
};

}  // namespace

ObjMesh read_obj(const std::string& path, Diagnostics& diag, const SourceLocation& referenced_from) {
  // A FIFO or a device would block or stream forever: refuse anything but a regular file.
  std::string why = input_file_problem(path);
  std::ifstream in;
  if (why.empty()) {
    in.open(path, std::ios::binary);
    if (!in) why = std::string("cannot be opened: ") + error_text(errno);
  }
  if (!why.empty()) {
    if (referenced_from.known())
      diag.error(referenced_from, "OBJ file '" + path + "' " + why);
    else
      diag.error({path, 0, 0}, "OBJ file " + why);
    return {};
  }
  ObjParser parser(path, diag);
  parser.parse(in);
  return parser.take();
}

ObjMesh read_obj_from_string(const std::string& text, const std::string& path, Diagnostics& diag) {
  std::istringstream in(text);
  ObjParser parser(path, diag);
  parser.parse(in);
  return parser.take();
}

}  // namespace dayphoton::project
