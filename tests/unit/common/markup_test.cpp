#include <gtest/gtest.h>

#include "facet/markup.h"

namespace facet {
namespace {

TEST(Markup, XmlEscapeReplacesTheFourMarkupCharactersAndKeepsTheRest) {
  EXPECT_EQ(xml_escape(R"(a<b> & "c" 'd' é)"), "a&lt;b&gt; &amp; &quot;c&quot; 'd' é");
  EXPECT_EQ(xml_escape("&amp;"), "&amp;amp;");  // escaping is not idempotent: escape once
  EXPECT_EQ(xml_escape(""), "");
}

}  // namespace
}  // namespace facet
