// The XML scanner on its own: events, encodings, references, errors and positions, and
// markup that spans the 1 MiB buffer refill.
#include "track/io/xml_stream.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace trailray::track;

namespace {

// Records events as "<name a=v>", "</name|text>", and the position of each start.
class Recorder final : public XmlHandler {
 public:
  std::vector<std::string> events;
  std::vector<SourcePosition> starts;
  void start_element(std::string_view name, const char** attrs) override {
    std::string e = "<" + std::string(name);
    for (const char** a = attrs; *a; a += 2) e += std::string(" ") + a[0] + "=" + a[1];
    events.push_back(e + ">");
    starts.push_back(position());
  }
  void end_element(std::string_view name, std::string_view text) override {
    events.push_back("</" + std::string(name) + "|" + std::string(text) + ">");
  }
};

XmlParseOutcome scan(const std::string& doc, Recorder& r) {
  auto src = ByteSource::from_memory(doc, "t.xml");
  return XmlStream::parse(*src, r);
}

}  // namespace

TEST(XmlStream, EventsAttributesAndText) {
  Recorder r;
  auto out = scan("<?xml version='1.0'?>\n<a x=\"1\" y='two'><b:c>hi</b:c><d/></a>", r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Complete) << out.message;
  std::vector<std::string> want{"<a x=1 y=two>", "<c>", "</c|hi>", "<d>", "</d|>", "</a|>"};
  EXPECT_EQ(r.events, want);
  EXPECT_EQ(r.starts[1].line, 2);
  EXPECT_EQ(r.starts[1].column, 18);  // the "<" of <b:c>
}

TEST(XmlStream, ReferencesCdataAndCommentsInText) {
  Recorder r;
  auto out = scan(R"(<a t="&lt;&#65;&#x42;&quot;">x &amp; y<!-- no --><![CDATA[ <z> ]]>&#xE9;</a>)", r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Complete) << out.message;
  EXPECT_EQ(r.events[0], "<a t=<AB\">");
  EXPECT_EQ(r.events[1], "</a|x & y <z> \xC3\xA9>");
}

TEST(XmlStream, Latin1AndWindows1252AreConvertedToUtf8) {
  Recorder r;
  auto out = scan("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a>Z\xFCrich</a>", r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Complete) << out.message;
  EXPECT_EQ(r.events[1], "</a|Z\xC3\xBCrich>");
  Recorder w;
  ASSERT_EQ(scan("<?xml version=\"1.0\" encoding=\"windows-1252\"?><a>\x80</a>", w).kind,
            XmlParseOutcome::Kind::Complete);
  EXPECT_EQ(w.events[1], "</a|\xE2\x82\xAC>");  // the euro sign
}

TEST(XmlStream, Utf16BigEndianWithoutBom) {
  std::string doc;
  for (char c : std::string("<?xml version=\"1.0\"?><a>\x7F</a>")) doc += std::string{'\0', c};
  Recorder r;
  auto out = scan(doc, r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Complete) << out.message;
  EXPECT_EQ(r.events[1], "</a|\x7F>");
}

TEST(XmlStream, UnsupportedEncodingIsAnError) {
  Recorder r;
  auto out = scan("<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><a/>", r);
  EXPECT_EQ(out.kind, XmlParseOutcome::Kind::Error);
  EXPECT_NE(out.message.find("shift_jis"), std::string::npos) << out.message;
}

TEST(XmlStream, UndefinedEntityIsAnErrorWithPosition) {
  Recorder r;
  auto out = scan("<a>\n  x &nbsp; y</a>", r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Error);
  EXPECT_NE(out.message.find("undefined entity '&nbsp;'"), std::string::npos) << out.message;
  EXPECT_EQ(out.position.line, 2);
  EXPECT_EQ(out.position.column, 5);
}

TEST(XmlStream, JunkAfterTheDocumentAndTwoRoots) {
  Recorder r;
  EXPECT_EQ(scan("<a/>\n<b/>", r).message, "malformed XML: junk after document element");
  Recorder s;
  EXPECT_EQ(scan("<a/> text", s).message, "malformed XML: junk after document element");
}

TEST(XmlStream, EmptyInputAndWhitespaceOnly) {
  Recorder r;
  auto out = scan("  \n ", r);
  EXPECT_EQ(out.kind, XmlParseOutcome::Kind::Error);
  EXPECT_EQ(out.message, "not an XML document: no element found");
}

TEST(XmlStream, BadTokensAreErrorsNotCrashes) {
  for (const char* doc : {"<a><b></a>", "<a x=1/>", "<a x=\"1\"y=\"2\"/>", "<a x=\"<\"/>", "<1a/>", "<a></ a>",
                          "<a>&#0;</a>", "<a>&#xD800;</a>", "<a>&#99999999999;</a>", "<a>& b</a>", "<!bogus><a/>"}) {
    Recorder r;
    auto out = scan(doc, r);
    EXPECT_EQ(out.kind, XmlParseOutcome::Kind::Error) << doc;
    EXPECT_GE(out.position.line, 1) << doc;
  }
}

TEST(XmlStream, CutInsideATagIsTruncationAfterTheRoot) {
  Recorder r;
  auto out = scan("<a><b>1</b><b x=\"2", r);
  EXPECT_EQ(out.kind, XmlParseOutcome::Kind::Truncated);
  EXPECT_EQ(r.events.size(), 3u);  // <a>, <b>, </b>: the cut tag gives no event
  Recorder s;
  EXPECT_EQ(scan("<a", s).kind, XmlParseOutcome::Kind::Error);  // nothing read: not a document
}

TEST(XmlStream, MarkupAndTextAcrossTheBufferRefillKeepTheirValuesAndLines) {
  // Put tags, a long text value and a comment astride the 1 MiB refill boundary.
  std::string doc = "<root>\n";
  int lines = 2;
  while (doc.size() < (1u << 20) - 40) {
    doc += "<p a=\"12345\">value</p>\n";
    ++lines;
  }
  doc +=
      "<long>" + std::string(200000, 'x') + "</long>\n<!-- a comment\nover lines -->\n<last k='v'>end</last>\n</root>";
  lines += 3;
  Recorder r;
  auto out = scan(doc, r);
  ASSERT_EQ(out.kind, XmlParseOutcome::Kind::Complete) << out.message;
  std::size_t p = 0;
  for (const auto& e : r.events) p += e == "</p|value>";
  EXPECT_EQ(p, std::size_t(lines - 5));
  ASSERT_GE(r.events.size(), 4u);
  EXPECT_EQ(r.events[r.events.size() - 4], "</long|" + std::string(200000, 'x') + ">");
  EXPECT_EQ(r.events[r.events.size() - 3], "<last k=v>");
  EXPECT_EQ(r.starts.back().line, lines);  // <long> on lines-3, the comment on lines-2 and -1
}
