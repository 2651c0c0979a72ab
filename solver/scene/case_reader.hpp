#pragma once
// Strict reader of one case-file table: each key is consumed as it is read; what is left over is
// an unknown key and rejected. Every error names the file, the dotted key and what was expected.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "scene/case_file.hpp"

namespace psph {

inline std::string toml_line_of(const toml::node& n) {
  const auto& src = n.source();
  return src.begin.line ? " (line " + std::to_string(src.begin.line) + ")" : "";
}

// A value or key as an error message shows it: at most `most` bytes (then "..."), control
// characters, bidirectional overrides and bytes that are not UTF-8 written as \xNN, so that a
// hostile case file cannot flood the terminal or rewrite it.
inline std::string shown(const std::string& s, std::size_t most = 80) {
  std::string out;
  auto hex = [&](unsigned char b) {
    const char* d = "0123456789abcdef";
    out += "\\x", out += d[b >> 4], out += d[b & 15];
  };
  std::size_t i = 0;
  while (i < s.size() && out.size() < most) {
    const unsigned char b = static_cast<unsigned char>(s[i]);
    const int len = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    bool ok = len > 0 && i + len <= s.size();
    for (int k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(s[i + k]) >> 6) == 2;
    const bool bidi = ok && len == 3 && b == 0xe2 && static_cast<unsigned char>(s[i + 1]) == 0x80 &&
                      (static_cast<unsigned char>(s[i + 2]) >= 0xaa && static_cast<unsigned char>(s[i + 2]) <= 0xae);
    const bool isolate = ok && len == 3 && b == 0xe2 && static_cast<unsigned char>(s[i + 1]) == 0x81 &&
                         (static_cast<unsigned char>(s[i + 2]) >= 0xa6 && static_cast<unsigned char>(s[i + 2]) <= 0xa9);
    if (!ok || (len == 1 && (b < 0x20 || b == 0x7f)) || bidi || isolate) {
      hex(b);
      ++i;
      continue;
    }
    out.append(s, i, len);
    i += len;
  }
  if (i < s.size()) out += "...";
  return out;
}

// Reads one table and remembers which keys were used.
class CaseReader {
 public:
  CaseReader(const toml::table& t, std::string file, std::string path)
      : t_(t), file_(std::move(file)), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& expected, const toml::node* n = nullptr) const {
    throw CaseError(file_ + ": " + shown(qualified(key), 200) + (n ? toml_line_of(*n) : "") + ": " + expected);
  }
  std::string qualified(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const toml::node* node(const std::string& key) {
    used_.insert(key);
    return t_.get(key);
  }
  bool has(const std::string& key) const { return t_.contains(key); }

  double number(const std::string& key, std::optional<double> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected a number)");
    }
    if (auto v = n->value<double>()) return checked_number(key, *v, n);  // integers convert too
    fail(key, std::string("expected a number, got ") + type_name(*n), n);
  }
  // Every number of a case file: finite, and 0 or of a magnitude in [kSmallest, kLargest] (no
  // SI quantity of a pore-scale case comes near either bound; subnormal values would stall a run).
  static constexpr double kSmallest = 1e-30, kLargest = 1e15;
  double checked_number(const std::string& key, double v, const toml::node* n) const {
    const double a = std::fabs(v);
    if (!std::isfinite(v) || a > kLargest || (a > 0 && a < kSmallest))
      fail(key, "expected a finite number, 0 or of magnitude in [1e-30, 1e15], got " + fmt(v), n);
    return v;
  }
  double positive(const std::string& key, std::optional<double> def = std::nullopt) {
    const double v = number(key, def);
    if (!(v > 0) || !std::isfinite(v)) fail(key, "expected a number > 0, got " + fmt(v), node(key));
    return v;
  }
  double non_negative(const std::string& key, std::optional<double> def = std::nullopt) {
    const double v = number(key, def);
    if (!(v >= 0) || !std::isfinite(v)) fail(key, "expected a number >= 0, got " + fmt(v), node(key));
    return v;
  }
  long integer(const std::string& key, std::optional<long> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected an integer)");
    }
    if (auto v = n->value_exact<int64_t>()) return static_cast<long>(*v);
    fail(key, std::string("expected an integer, got ") + type_name(*n), n);
  }
  long positive_integer(const std::string& key, long def) {
    const long v = integer(key, def);
    if (v < 1) fail(key, "expected an integer >= 1, got " + std::to_string(v), node(key));
    return v;
  }
  std::string string(const std::string& key, std::optional<std::string> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected a string)");
    }
    if (auto v = n->value_exact<std::string>()) return *v;
    fail(key, std::string("expected a string, got ") + type_name(*n), n);
  }
  std::string choice(const std::string& key, const std::vector<std::string>& options,
                     std::optional<std::string> def = std::nullopt) {
    const std::string v = string(key, def);
    for (const auto& o : options)
      if (o == v) return v;
    std::string list;
    for (const auto& o : options) list += (list.empty() ? "" : ", ") + ("\"" + o + "\"");
    fail(key, "expected one of " + list + ", got \"" + shown(v) + "\"", node(key));
  }
  // An axis named "x", "y" or "z" of a `dim`-dimensional case, as 0, 1 or 2.
  int axis(const std::string& key, int dim, std::optional<std::string> def = std::nullopt) {
    static const std::vector<std::string> names{"x", "y", "z"};
    const std::string v = choice(key, names, def);
    const int a = static_cast<int>(std::find(names.begin(), names.end(), v) - names.begin());
    if (a >= dim) fail(key, "expected an axis of this " + std::to_string(dim) + "D case, got \"" + shown(v) + "\"", node(key));
    return a;
  }
  bool boolean(const std::string& key, bool def) {
    const toml::node* n = node(key);
    if (!n) return def;
    if (auto v = n->value_exact<bool>()) return *v;
    fail(key, std::string("expected true or false, got ") + type_name(*n), n);
  }
  // A box: `lower` and `upper` (dim numbers each), upper > lower on every axis.
  void box(int dim, std::array<double, 3>& lower, std::array<double, 3>& upper) {
    lower = vec<double>("lower", dim);
    upper = vec<double>("upper", dim);
    for (int k = 0; k < dim; ++k)
      if (!(upper[k] > lower[k])) fail("upper", "expected upper > lower on every axis (axis " + std::to_string(k) + ")");
  }
  // An array of exactly `dim` numbers (or booleans when `T` is bool).
  template <class T>
  std::array<T, 3> vec(const std::string& key, int dim, std::optional<std::array<T, 3>> def = std::nullopt) {
    const toml::node* n = node(key);
    const char* what = std::is_same_v<T, bool> ? "booleans" : "numbers";
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected an array of " + std::to_string(dim) + " " + what + ")");
    }
    const toml::array* arr = n->as_array();
    if (!arr || static_cast<int>(arr->size()) != dim)
      fail(key, "expected an array of " + std::to_string(dim) + " " + what + " (one per dimension)", n);
    std::array<T, 3> out{};
    for (int k = 0; k < dim; ++k) {
      std::optional<T> v;
      if constexpr (std::is_same_v<T, bool>) v = (*arr)[k].value_exact<bool>();
      else v = (*arr)[k].value<T>();
      if (!v) fail(key, "expected an array of " + std::to_string(dim) + " " + what, n);
      if constexpr (std::is_same_v<T, double>) checked_number(key, *v, n);
      out[k] = *v;
    }
    return out;
  }
  std::vector<std::string> strings(const std::string& key, std::vector<std::string> def) {
    const toml::node* n = node(key);
    if (!n) return def;
    const toml::array* arr = n->as_array();
    if (!arr) fail(key, "expected an array of strings", n);
    std::vector<std::string> out;
    for (const auto& e : *arr) {
      auto v = e.value_exact<std::string>();
      if (!v) fail(key, "expected an array of strings", n);
      out.push_back(*v);
    }
    return out;
  }
  const toml::table& table(const std::string& key, bool required) {
    const toml::node* n = node(key);
    static const toml::table empty;
    if (!n) {
      if (required) fail(key, "missing required table [" + qualified(key) + "]");
      return empty;
    }
    if (!n->is_table()) fail(key, "expected a table", n);
    return *n->as_table();
  }
  // Reads each table of the array of tables [[key]] (none when absent; at most `most`, called
  // `plural` in the message) with a reader named key[i], then refuses its unknown keys.
  template <class F>
  void each_table(const std::string& key, std::size_t most, const std::string& plural, F&& read) {
    const toml::node* g = node(key);
    if (!g) return;
    const toml::array* arr = g->as_array();
    if (!arr || !arr->is_array_of_tables()) fail(key, "expected an array of tables [[" + key + "]]", g);
    if (arr->size() > most) fail(key, "expected at most " + std::to_string(most) + " " + plural, g);
    int idx = 0;
    for (const auto& e : *arr) {
      CaseReader r(*e.as_table(), file_, qualified(key) + "[" + std::to_string(idx++) + "]");
      read(r);
      r.finish();
    }
  }
  // Rejects every key that was not read.
  void finish() const {
    for (const auto& [k, v] : t_) {
      const std::string key(k.str());
      if (!used_.count(key)) fail(key, "unknown key", &v);
    }
  }

  static const char* type_name(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string: return "a string";
      case toml::node_type::integer: return "an integer";
      case toml::node_type::floating_point: return "a number";
      case toml::node_type::boolean: return "a boolean";
      case toml::node_type::array: return "an array";
      case toml::node_type::table: return "a table";
      default: return "a date or time";
    }
  }
  static std::string fmt(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  }

 private:
  const toml::table& t_;
  std::string file_, path_;
  std::set<std::string> used_;
};

}  // namespace psph
