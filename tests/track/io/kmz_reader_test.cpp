// The KMZ reader on archives built here: which entries are read, diagnostics naming the entry,
// damaged archives and zip bombs.
#include <gtest/gtest.h>

#include <string>

#include "track/io/byte_source.hpp"
#include "track/io/readers.hpp"
#include "zip_builder.hpp"

using namespace trailray::track;
using trailray::test::make_zip;

namespace {

ReadResult read(const std::string& bytes, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(bytes, "test.kmz");
  return read_kmz(*src, options);
}

std::string kml(const std::string& doc_name, const std::string& body) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n"
         "<Document><name>" +
         doc_name + "</name>\n" + body + "</Document>\n</kml>\n";
}

std::string line(const std::string& name, const std::string& coordinates) {
  return "<Placemark><name>" + name + "</name><LineString><coordinates>" + coordinates +
         "</coordinates></LineString></Placemark>\n";
}

}  // namespace

TEST(KmzReader, DocKmlIsReadAloneWhenPresent) {
  std::string zip = make_zip({{"other.kml", kml("Other", line("X", "1,1 2,2"))},
                              {"doc.kml", kml("Main", line("A", "3,3 4,4 5,5"))},
                              {"files/icon.png", "\x89PNG"}});
  ASSERT_FALSE(zip.empty());
  ReadResult r = read(zip);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file.format, Format::Kmz);
  EXPECT_EQ(r.file.metadata.name, "Main");
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_EQ(r.file.tracks[0].name, "A");
  EXPECT_EQ(r.file.tracks[0].point_count(), 3u);
}

TEST(KmzReader, WithoutDocKmlEveryKmlEntryIsReadInOrder) {
  std::string zip = make_zip(
      {{"b/track1.kml", kml("First", line("A", "1,1 2,2"))},
       {"__MACOSX/b/._track1.kml", "\0\x05\x16\x07 not xml"},
       {"readme.txt", "hello"},
       {"track2.KML", kml("Second", line("B", "3,3 4,4 5,5") + "<Placemark><name>W</name><Point><coordinates>6,6"
                                                               "</coordinates></Point></Placemark>")}});
  ReadResult r = read(zip);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file.metadata.name, "First");
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].name, "A");
  EXPECT_EQ(r.file.tracks[1].name, "B");
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "W");
}

TEST(KmzReader, WarningsAndErrorsNameTheEntry) {
  std::string good = kml("G", line("A", "1,1 2,2"));
  std::string warned = kml("W", line("B", "\n\n3,3 999,4"));
  std::string broken = "<kml>\n<Document>\n<Placemark></Folder>";
  ReadResult r = read(make_zip({{"one.kml", good}, {"two.kml", warned}}));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].file, "test.kmz:two.kml");
  EXPECT_EQ(r.warnings[0].position.line, 6);
  EXPECT_NE(r.warnings[0].to_string().find("test.kmz:two.kml:6:"), std::string::npos) << r.warnings[0].to_string();

  ReadResult e = read(make_zip({{"one.kml", good}, {"bad.kml", broken}}));
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error->file, "test.kmz:bad.kml");
  EXPECT_EQ(e.error->position.line, 3);
  EXPECT_NE(e.error->message.find("mismatched tag"), std::string::npos);

  ReadOptions strict;
  strict.strict = true;
  ReadResult s = read(make_zip({{"one.kml", good}, {"two.kml", warned}}), strict);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error->file, "test.kmz:two.kml");
}

TEST(KmzReader, ArchiveWithoutKmlIsAnErrorListingItsEntries) {
  ReadResult r = read(make_zip({{"notes.txt", "x"}, {"image.bmp", "BM"}}));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, "test.kmz");
  EXPECT_NE(r.error->message.find("no KML document"), std::string::npos) << r.error->message;
  EXPECT_NE(r.error->message.find("notes.txt, image.bmp"), std::string::npos) << r.error->message;
}

TEST(KmzReader, DamagedArchivesAreErrors) {
  ReadResult garbage = read(std::string("PK\x03\x04", 4) + std::string(200, 'x'));
  ASSERT_FALSE(garbage.ok());
  EXPECT_NE(garbage.error->message.find("not a readable zip archive"), std::string::npos);

  std::string zip = make_zip({{"doc.kml", kml("D", line("A", "1,1 2,2"))}});
  ReadResult cut = read(zip.substr(0, zip.size() - 10));  // the end of the central directory is gone
  ASSERT_FALSE(cut.ok());

  // Deflated data changed: the entry's checksum (or its XML) no longer holds.
  std::string payload = kml("D", line("A", std::string(3000, ' ') + "1,1 2,2"));
  std::string bent = make_zip({{"doc.kml", payload}});
  const std::size_t data_at = 30 + 7 + 10;  // past the local header and the name, into the data
  ASSERT_GT(bent.size(), data_at);
  bent[data_at] = static_cast<char>(bent[data_at] ^ 0x55);
  ReadResult damaged = read(bent);
  EXPECT_FALSE(damaged.ok());
  EXPECT_EQ(damaged.error->file, "test.kmz:doc.kml");
}

TEST(KmzReader, ZipBombIsRefusedByTheDecompressedBudget) {
  // 4 MB of empty folders deflate to a few kB.
  std::string folders;
  for (int i = 0; i < (4 << 20) / 10; ++i) folders += "<Folder/>\n";
  std::string big = kml("Big", folders + line("A", "1,1 2,2"));
  std::string zip = make_zip({{"doc.kml", big}});
  ASSERT_LT(zip.size(), 64u << 10);
  ReadOptions small;
  small.kmz_max_bytes = 1 << 20;
  ReadResult r = read(zip, small);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, "test.kmz:doc.kml");
  EXPECT_NE(r.error->message.find("zip bomb"), std::string::npos) << r.error->message;
  // Under the default budget the same archive is read.
  ReadResult fine = read(zip);
  ASSERT_TRUE(fine.ok()) << fine.error->to_string();
  EXPECT_EQ(fine.file.tracks[0].point_count(), 2u);

  ReadOptions tiny;
  tiny.kmz_max_bytes = 100;  // the archive itself is over it
  ReadResult too_big = read(zip, tiny);
  ASSERT_FALSE(too_big.ok());
  EXPECT_EQ(too_big.error->file, "test.kmz");
}
