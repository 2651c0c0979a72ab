// Strict case-file reader: each table is read by its own reader (scene/case_tables.hpp), whose keys
// are consumed as they are read (what is left over is an unknown key and rejected); then the
// checks between tables.
#include "scene/case_file.hpp"

#include "scene/case_tables.hpp"
#include "scene/sample_table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace psph {

// The tables' readers (scene/read_*.cpp), in the order parse_case calls them.
void read_case_table(CaseReader& top, CaseDraft& d);       // [case]
void read_domain(CaseReader& top, CaseDraft& d);           // [domain]
void read_discretisation(CaseReader& top, CaseDraft& d);   // [discretisation]
void read_materials(CaseReader& top, CaseDraft& d);        // [materials.*]
void read_solid(CaseReader& top, CaseDraft& d);            // [solid]
void read_damage(CaseReader& top, CaseDraft& d);           // [damage]
void read_body_force_regions(CaseReader& top, CaseDraft& d);  // [[body_force_region]]
void read_solid_loads(CaseReader& top, CaseDraft& d);      // [[solid_load]]
void read_open_boundary(CaseReader& top, CaseDraft& d);    // [open_boundary]
void read_interface(CaseReader& top, CaseDraft& d);        // [interface]
void read_solver(CaseReader& top, CaseDraft& d);           // [solver]
void read_time_and_output(CaseReader& top, CaseDraft& d);  // [time], [output], [visualisation]
void read_monitors(CaseReader& top, CaseDraft& d);         // [monitors]
void read_probes(CaseReader& top, CaseDraft& d);           // [[probe]]
void read_geometry(CaseReader& top, CaseDraft& d);         // [[geometry]]

Case parse_case(const toml::table& given, const std::string& file) {
  if (given.contains("sample")) {  // a copy: toml++ drops the lines of copied nodes (load_case_text expands in place)
    toml::table copy = given;
    expand_sample(copy, file);
    return parse_case(copy, file);
  }
  const toml::table& tbl = given;
  Case c;
  c.file = file;
  CaseDraft d(c, file);
  CaseReader top(tbl, file, "");
  read_case_table(top, d);
  read_domain(top, d);
  read_discretisation(top, d);
  read_materials(top, d);
  read_solid(top, d);
  read_damage(top, d);
  read_body_force_regions(top, d);
  read_solid_loads(top, d);
  read_open_boundary(top, d);
  read_interface(top, d);
  read_solver(top, d);
  read_time_and_output(top, d);
  read_monitors(top, d);
  read_probes(top, d);
  read_geometry(top, d);
  top.finish();
  cross_check(d);
  // The resolved case names each image by the path it was found at.
  toml::table resolved = tbl;
  for (const auto& [index, path] : d.image_files)
    resolved["geometry"].as_array()->at(index).as_table()->insert_or_assign("file", path);
  std::ostringstream os;
  os << resolved;
  c.source_text = os.str();
  return c;
}

namespace {

constexpr std::size_t kMaxCaseBytes = 1 << 20;  // a case file is a few kB; its images are separate files
constexpr int kMaxNesting = 64;                 // tables and arrays within each other

// What is checked before toml++ sees the text, outside strings and comments: the deepest nesting
// of tables (dotted headers and keys) and of arrays and inline tables (toml++ parses by recursion:
// a file nested 100,000 levels deep would overflow the stack), and the first byte that is not
// ASCII there or that follows a line-ending backslash in a string (TOML allows neither outside
// strings; toml++ 3.3 reaches undefined behaviour classifying such a character as whitespace).
struct TextScan {
  int deepest = 0, deepest_line = 1, bad_line = 0;
};

TextScan scan_case_text(const std::string& text) {
  TextScan r;
  int line = 1, brackets = 0, dots = 0;
  char quote = 0;
  bool comment = false, key = true, header = false;  // key: before '=' on a line outside a value
  for (std::size_t i = 0; i < text.size() && !r.bad_line; ++i) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line, comment = false, dots = 0, header = false, key = brackets == 0;
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (ch == '\\' && quote == '"' && i + 1 < text.size() && std::isspace(static_cast<unsigned char>(text[i + 1])))
        r.bad_line = line;
      else if (ch == '\\' && quote == '"') ++i;
      else if (ch == quote) quote = 0;
      continue;
    }
    if (static_cast<unsigned char>(ch) >= 0x80) r.bad_line = line;
    else if (ch == '"' || ch == '\'') quote = ch;
    else if (ch == '#') comment = true;
    else if (ch == '[' && key && brackets == 0) header = true, key = false, ++brackets;
    else if (ch == '[' || ch == '{') ++brackets;
    else if (ch == ']' || ch == '}') brackets = brackets > 0 ? brackets - 1 : 0;
    else if (ch == '.' && (key || (header && brackets > 0))) ++dots;  // a dotted key or table header
    else if (ch == '=') key = false;
    if (brackets + dots > r.deepest) r.deepest = brackets + dots, r.deepest_line = line;
  }
  return r;
}

}  // namespace

namespace {

// A dotted key of letters, digits, '_' and '-'.
bool valid_dotted_key(const std::string& key) {
  return !key.empty() && key.front() != '-' && key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") == std::string::npos &&
         key.front() != '.' && key.back() != '.' && key.find("..") == std::string::npos;
}

// KEY removed from `tbl` (--unset).
void apply_unset(toml::table& tbl, const std::string& key, const std::string& file) {
  toml::table* t = &tbl;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) {
    t = t->get_as<toml::table>(key.substr(start, dot - start));
    if (!t) break;
  }
  if (!t || !t->contains(key.substr(start)))
    throw CaseError(file + ": --unset " + shown(key) + ": expected a key or table the case file sets");
  t->erase(key.substr(start));
}

// "KEY=VALUE" into `tbl`, or "!KEY" out of it (load_case_text's sets).
void apply_set(toml::table& tbl, const std::string& set, const std::string& file) {
  if (!set.empty() && set[0] == '!') {
    if (!valid_dotted_key(set.substr(1)))
      throw CaseError(file + ": --unset " + shown(set.substr(1)) + ": expected a dotted key of letters, digits, '_' and '-'");
    return apply_unset(tbl, set.substr(1), file);
  }
  const std::size_t eq = set.find('=');
  const std::string key = eq == std::string::npos ? "" : set.substr(0, eq), text = eq == std::string::npos ? "" : set.substr(eq + 1);
  if (!valid_dotted_key(key) || text.empty() || text.size() > 4096)
    throw CaseError(file + ": --set " + shown(set) + ": expected KEY=VALUE with a dotted key of letters, digits, '_' "
                    "and '-' (e.g. sample.confinement=0.16)");
  const TextScan scan = scan_case_text("v = " + text);  // what a case file's text must pass, too
  if (scan.bad_line || scan.deepest > kMaxNesting)
    throw CaseError(file + ": --set " + shown(set) + ": expected an ASCII TOML value nested at most " +
                    std::to_string(kMaxNesting) + " deep");
  toml::table value;
  try {
    value = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    value = toml::table{{"v", text}};  // a bare word: a string
  }
  try {
    set_case_value(tbl, key, *value.get("v"));
  } catch (const std::logic_error&) {
    throw CaseError(file + ": --set " + shown(set) + ": expected a key inside tables, not inside an array of tables or a value");
  }
}

}  // namespace

Case load_case_text(const std::string& text, const std::string& file, const std::vector<std::string>& sets) {
  if (text.size() > kMaxCaseBytes)
    throw CaseError(file + ": the case file holds " + std::to_string(text.size()) + " bytes; expected at most " +
                    std::to_string(kMaxCaseBytes) + " (1 MiB)");
  const TextScan scan = scan_case_text(text);
  if (scan.deepest > kMaxNesting)
    throw CaseError(file + " (line " + std::to_string(scan.deepest_line) + "): tables or arrays nested " +
                    std::to_string(scan.deepest) + " deep; expected at most " + std::to_string(kMaxNesting));
  if (scan.bad_line)
    throw CaseError(file + " (line " + std::to_string(scan.bad_line) + "): not valid TOML here: expected ASCII outside "
                    "strings and comments, and no line-ending backslash in a string");
  toml::table tbl;
  try {
    tbl = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw CaseError(file + " (line " + std::to_string(e.source().begin.line) + "): not valid TOML: " +
                    shown(std::string(e.description()), 200));
  }
  for (const std::string& set : sets) apply_set(tbl, set, file);
  expand_sample(tbl, file);  // [sample] -> the tables it stands for (scene/sample_table.hpp)
  return parse_case(tbl, file);
}

// Only a regular file of bounded size is read: a FIFO or a device would block or never end.
Case load_case_file(const std::string& path, const std::vector<std::string>& sets) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw CaseError(path + ": cannot open the case file");
  if (!std::filesystem::is_regular_file(status))
    throw CaseError(path + ": expected a regular file (a directory, FIFO or device is not a case file)");
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxCaseBytes)
    throw CaseError(path + ": the case file holds " + std::to_string(size) + " bytes; expected at most " +
                    std::to_string(kMaxCaseBytes) + " (1 MiB)");
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open the case file");
  std::string text(kMaxCaseBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return load_case_text(text, path, sets);
}

void set_case_value(toml::table& tbl, const std::string& dotted_key, const toml::node& value) {
  toml::table* t = &tbl;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = dotted_key.find('.', start);
    const std::string part = dotted_key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (dot == std::string::npos) {
      value.visit([&](auto&& v) { t->insert_or_assign(part, v); });
      return;
    }
    toml::node* next = t->get(part);
    if (!next) {
      t->insert(part, toml::table{});
      next = t->get(part);
    }
    if (!next->is_table()) throw std::logic_error("set_case_value: " + dotted_key + " crosses a non-table");
    t = next->as_table();
    start = dot + 1;
  }
}

void set_case_spacing(toml::table& tbl, double spacing) {
  toml::table& disc = *tbl["discretisation"].as_table();
  const double f = spacing / *disc["spacing"].value<double>();
  for (const char* key : {"support_radius", "smoothing_length"})
    if (const auto v = disc[key].value<double>()) disc.insert_or_assign(key, *v * f);
  disc.insert_or_assign("spacing", spacing);
}

}  // namespace psph
