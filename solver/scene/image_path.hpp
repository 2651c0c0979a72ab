#pragma once
// Where an image geometry's `file` is: an absolute path as it is; a relative one next to the case
// file, else in each folder of the environment's PORESPH_IMAGE_PATH (separated by ':'), else in
// the folders this build knows (the checkout's cases/ and the rock images it found). The first
// that exists wins; `tried` gets every candidate (for the message when none does).
#include <string>
#include <vector>

namespace psph {

// The resolved path (absolute), or "" with `tried` filled when no candidate exists.
std::string find_image_file(const std::string& file, const std::string& case_file, std::vector<std::string>& tried);

}  // namespace psph
