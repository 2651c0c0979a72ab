#pragma once
// A segmented image that cannot be read as described: the message names the file and what was
// expected; `topic` says which part of the description ("crop", "coarsen", "labels"; empty: the
// file itself), for the case reader to name its key.
#include <stdexcept>
#include <string>

namespace psph {

class ImageError : public std::runtime_error {
 public:
  ImageError(const std::string& file, const std::string& what, std::string topic = "")
      : std::runtime_error(file + ": " + what), topic_(std::move(topic)) {}
  const std::string& topic() const { return topic_; }

 private:
  std::string topic_;
};

}  // namespace psph
