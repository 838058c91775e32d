// Hostile and broken input: findings, never a crash or an exception.
#include <gtest/gtest.h>

#include <tinyxml2.h>

#include "base/files.hpp"
#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"

namespace uabt::bt {
namespace {

using testing::describe;

// Parses text that must be refused with exactly one bt-xml finding; returns it.
Finding refused(const std::string& text) {
  std::vector<Finding> findings;
  std::optional<Document> doc;
  EXPECT_NO_THROW(doc = parse_document(text, "bad.xml", findings));
  EXPECT_FALSE(doc.has_value());
  EXPECT_EQ(findings.size(), 1u) << describe(findings);
  if (findings.empty()) return Finding{};
  EXPECT_EQ(findings[0].check, "bt-xml");
  EXPECT_EQ(findings[0].severity, Severity::error);
  EXPECT_EQ(findings[0].location.file, "bad.xml");
  return findings[0];
}

TEST(Hostile, MismatchedClosingTagNamesItsLine) {
  const Finding f = refused(
      "<root BTCPP_format=\"4\">\n"
      "  <BehaviorTree ID=\"MainTree\">\n"
      "    <Sequence>\n"
      "      <MoveForward speed=\"2\"/>\n"
      "  </BehaviorTree>\n"
      "</root>\n");
  EXPECT_EQ(f.location.line, 5);
  EXPECT_EQ(f.location.column, 3);
  EXPECT_EQ(f.message, "</BehaviorTree> does not close <Sequence>, opened at line 3, column 5");
}

TEST(Hostile, UnquotedAttribute) {
  const Finding f = refused("<root>\n<BehaviorTree ID=A><X/></BehaviorTree></root>");
  EXPECT_EQ(f.location.line, 2);
  EXPECT_NE(f.message.find("attribute"), std::string::npos) << f.message;
}

TEST(Hostile, UnclosedDocument) {
  const Finding f = refused("<root>\n<BehaviorTree ID=\"A\">\n<X/>\n");
  EXPECT_EQ(f.message, "<BehaviorTree> is never closed");
  EXPECT_EQ(f.location.line, 2);
  EXPECT_EQ(f.location.column, 1);
  EXPECT_FALSE(refused("<root><BehaviorTree ID=\"A\"><X a=\"1").message.empty());
}

TEST(Hostile, EmptyAndBlankFiles) {
  EXPECT_EQ(refused("").message, "empty file: expected a <root> element");
  EXPECT_EQ(refused(" \r\n\t\n").message, "empty file: expected a <root> element");
  EXPECT_NE(refused("<!-- only a comment -->").message.find("no XML element"), std::string::npos);
}

TEST(Hostile, BinaryJunk) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 7919 + 13) % 256);
  junk[1000] = '\0';
  const Finding f = refused(junk);
  EXPECT_NE(f.message.find("binary content (a NUL byte at offset"), std::string::npos) << f.message;
  // Without NUL bytes, still not UTF-8.
  std::string high;
  for (int i = 0; i < 512; ++i) high += static_cast<char>(0x80 + i % 0x40);
  EXPECT_NE(refused(high).message.find("invalid UTF-8"), std::string::npos);
}

TEST(Hostile, InvalidUtf8IsLocated) {
  const Finding f =
      refused("<root>\n  <BehaviorTree ID=\"A\"><Say text=\"caf\xE9\"/></BehaviorTree></root>");
  EXPECT_NE(f.message.find("invalid UTF-8"), std::string::npos);
  EXPECT_EQ(f.location.line, 2);
  EXPECT_EQ(f.location.column, 38);
  // Overlong encodings and surrogates are invalid too.
  refused("<root><X a=\"\xC0\xBC\"/></root>");
  refused("<root><X a=\"\xED\xA0\x80\"/></root>");
}

TEST(Hostile, DtdAndEntitiesAreRefused) {
  const Finding doctype = refused(
      "<?xml version=\"1.0\"?>\n"
      "<!DOCTYPE root [<!ENTITY lol \"lol\"><!ENTITY lol2 \"&lol;&lol;&lol;\">]>\n"
      "<root><BehaviorTree ID=\"A\"><X a=\"&lol2;\"/></BehaviorTree></root>");
  EXPECT_NE(doctype.message.find("DTD not allowed"), std::string::npos);
  EXPECT_EQ(doctype.location.line, 2);
  EXPECT_EQ(doctype.location.column, 1);
  EXPECT_NE(refused("<!ENTITY x SYSTEM \"file:///etc/passwd\"><root/>").message.find("DTD"),
            std::string::npos);
  EXPECT_NE(refused("<root><!ELEMENT root ANY><BehaviorTree ID=\"A\"><X/></BehaviorTree></root>")
                .message.find("DTD not allowed"),
            std::string::npos);
  // Inside a comment it is only text.
  testing::parse_clean(
      "<root><!-- <!DOCTYPE x> --><BehaviorTree ID=\"A\"><X/></BehaviorTree></root>");
}

TEST(Hostile, StrayAmpersandsAreRefusedAndLocated) {
  // Found by fuzz_bt_xml (regressions/bt_xml/stray-ampersand-after-reference.xml): tinyxml2
  // turned "&#10;b\xC3\xA9&e" into "\nb\xC3\xA9\xC3e", a byte the text never had.
  const Finding f = refused(
      "<root>\n  <BehaviorTree ID=\"A\"><Say text=\"a&#10;b\xC3\xA9&e\"/></BehaviorTree></root>");
  EXPECT_NE(f.message.find("'&' must start a reference"), std::string::npos) << f.message;
  EXPECT_EQ(f.location.line, 2);
  EXPECT_EQ(f.location.column, 43);
  EXPECT_NE(refused("<root><BehaviorTree ID=\"A\"><X/>Tom & Jerry</BehaviorTree></root>")
                .message.find("'&' must start a reference"),
            std::string::npos);
  refused("<root><X a=\"&#;\"/></root>");
  refused("<root><X a=\"&#x;\"/></root>");
  refused("<root><X a=\"&amp\"/></root>");
  // Every reference XML defines without a DTD is fine, in values and in text; in a comment or
  // CDATA section '&' is only text.
  const bt::Document doc = testing::parse_clean(
      "<root><BehaviorTree ID=\"A\"><Script code=\"a &lt; b &amp;&amp; c &gt; d &apos;&quot; "
      "&#10;&#x41;\"/><!-- & --></BehaviorTree></root>");
  EXPECT_EQ(*doc.trees.at(0).root.attribute("code"), "a < b && c > d '\" \nA");
}

std::string nested(int depth) {
  std::string text = "<root><BehaviorTree ID=\"A\">";
  for (int i = 0; i < depth; ++i) text += "<Inverter>";
  text += "<X/>";
  for (int i = 0; i < depth; ++i) text += "</Inverter>";
  return text + "</BehaviorTree></root>";
}

TEST(Hostile, HundredThousandDeepIsAFindingNotACrash) {
  const Finding f = refused(nested(100000));
  EXPECT_NE(f.message.find("nested deeper than " + std::to_string(kMaxXmlDepth)), std::string::npos)
      << f.message;
  EXPECT_EQ(f.location.line, 1);
  // The first element too deep: <root>, <BehaviorTree>, then kMaxXmlDepth - 2 Inverters fit.
  EXPECT_EQ(f.location.column, 1 + 6 + 21 + (kMaxXmlDepth - 2) * 10);
}

// tinyxml2 refuses elements nested as deep as TINYXML2_MAX_ELEMENT_DEPTH (it counts the document
// and the innermost content too); uabt refuses them first, in its own words, at the element.
TEST(Hostile, TinyXml2DepthLimitIsUabtsLimit) {
  static_assert(kMaxXmlDepth == TINYXML2_MAX_ELEMENT_DEPTH - 2);
  // <root>, <BehaviorTree>, Inverters and <X/>: as deep as uabt's limit reads fine, even
  // written <X></X>, which tinyxml2 counts one deeper.
  for (const char* leaf : {"<X/>", "<X></X>"}) {
    std::string text = "<root><BehaviorTree ID=\"A\">";
    for (int i = 0; i < kMaxXmlDepth - 3; ++i) text += "<Inverter>";
    text += leaf;
    for (int i = 0; i < kMaxXmlDepth - 3; ++i) text += "</Inverter>";
    const Document doc = testing::parse_clean(text + "</BehaviorTree></root>");
    EXPECT_EQ(doc.trees.at(0).root.tag, "Inverter");
  }
  // One deeper is refused at the innermost element, an empty one too.
  const Finding f = refused(nested(kMaxXmlDepth - 2));
  EXPECT_NE(
      f.message.find("nested deeper than " + std::to_string(kMaxXmlDepth) + " levels: tinyxml2"),
      std::string::npos)
      << f.message;
  EXPECT_EQ(f.location.column, 1 + 6 + 21 + (kMaxXmlDepth - 2) * 10);
}

TEST(Hostile, OversizedFileIsRefused) {
  testing::TempDir dir;
  const std::filesystem::path big = dir.path() / "big.xml";
  {
    std::ofstream out(big, std::ios::binary);
    out << "<root>";
    out.seekp(static_cast<std::streamoff>(kMaxInputFileBytes) + 16);
    out << "</root>";
  }
  std::vector<Finding> findings;
  ReadOptions options;
  options.confine_to = dir.path();
  EXPECT_FALSE(read_document(big, options, findings).has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-xml");
  EXPECT_EQ(findings[0].location.file, "big.xml");
  EXPECT_NE(findings[0].message.find("limit"), std::string::npos) << findings[0].message;
}

TEST(Hostile, MissingFileAndDirectory) {
  testing::TempDir dir;
  std::vector<Finding> findings;
  ReadOptions options;
  options.confine_to = dir.path();
  EXPECT_FALSE(read_document(dir.path() / "nope.xml", options, findings).has_value());
  EXPECT_FALSE(read_document(dir.path(), options, findings).has_value());
  ASSERT_EQ(findings.size(), 2u);
  EXPECT_EQ(findings[0].location.file, "nope.xml");
  for (const Finding& f : findings) EXPECT_EQ(f.check, "bt-xml");
}

TEST(Hostile, StrayMarkup) {
  EXPECT_EQ(refused("<root><BehaviorTree ID=\"A\"><X/></BehaviorTree></root>\n</root>").message,
            "</root> closes no open element");
  refused("<root><!-- unterminated ");
  EXPECT_EQ(refused("< root/>").message, "'<' must start a tag; write &lt; for a literal '<'");
  refused("<root><BehaviorTree ID=\"A\"><X a=\"1></BehaviorTree></root>");
}

TEST(Hostile, RepeatedAttribute) {
  const Finding f =
      refused("<root><BehaviorTree ID=\"A\">\n  <X a=\"1\" a=\"2\"/></BehaviorTree></root>");
  EXPECT_EQ(f.location.line, 2);
  EXPECT_NE(f.message.find("given twice"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace uabt::bt
