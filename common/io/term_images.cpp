#include "common/io/term_images.h"

#include <filesystem>

#include "common/error.h"
#include "common/io/image_io.h"

namespace voxgi {

std::string termPath(const std::string& image, LightTerm term) {
  const std::filesystem::path p(image);
  return (p.parent_path() /
          (p.stem().string() + "." + std::string(termName(term)) + p.extension().string()))
      .string();
}

void writeTermImages(const std::string& image, const TermImages& terms) {
  for (const LightTerm term : kLightTerms) writeExr(termPath(image, term), termImage(terms, term));
}

TermImages readTermImages(const std::string& image) {
  TermImages terms;
  for (const LightTerm term : kLightTerms) {
    const std::string path = termPath(image, term);
    if (!std::filesystem::exists(path))
      throw InputError(path, "",
                       "missing: the terms of " + image +
                           " are written by voxgi render --terms (docs/accuracy.md)");
    termImage(terms, term) = readExr(path);
  }
  return terms;
}

}  // namespace voxgi
