#pragma once
// Helpers for tests that edit case-file text: a replacement that must match, and the CaseError
// message a text raises.
#include <string>

#include <gtest/gtest.h>

#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

namespace psph::test {

inline std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return p == std::string::npos ? s : s.replace(p, from.size(), to);
}

// The error message the case text raises when read and built as "bad.toml" (empty if accepted).
inline std::string error_of(const std::string& text) {
  try {
    Case c = load_case_text(text, "bad.toml");
    build_particles(c);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

// `text` with `from` replaced by `to` is refused with a message containing `says`.
inline void expect_refused(const std::string& text, const std::string& from, const std::string& to,
                           const std::string& says) {
  const std::string msg = error_of(replaced(text, from, to));
  EXPECT_NE(msg.find(says), std::string::npos) << msg;
}

}  // namespace psph::test
