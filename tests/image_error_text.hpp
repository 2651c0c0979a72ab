#pragma once
// The message of the image error `f` throws ("" when it throws none): for the image tests.
#include <functional>
#include <string>

#include "image/image_error.hpp"

namespace psph {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ImageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace psph
