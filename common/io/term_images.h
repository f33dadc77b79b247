// The light terms of an image as files beside it (docs/accuracy.md, "Error budget").
#pragma once

#include <string>

#include "common/light_terms.h"

namespace voxgi {

// Where the image of `term` goes beside IMAGE.exr: IMAGE.<term>.exr.
std::string termPath(const std::string& image, LightTerm term);

// Writes each term beside `image` (termPath), each file complete or not at all.
void writeTermImages(const std::string& image, const TermImages& terms);
// Reads the terms beside `image`; throws InputError naming a missing or unreadable file.
TermImages readTermImages(const std::string& image);

}  // namespace voxgi
