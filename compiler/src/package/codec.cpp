#include "codec.h"


namespace facet::package::codec {

std::string_view section_name(SectionId id) {
  switch (id) {
    case SectionId::strings: return "strings";
    case SectionId::shader: return "shader";
    case SectionId::properties: return "properties";
    case SectionId::passes: return "passes";
    case SectionId::keywords: return "keywords";
    case SectionId::variants: return "variants";
    case SectionId::blobs: return "blobs";
  }
  return "unknown";
}

}  // namespace facet::package::codec
