// `trailray serve`'s photos and places for the page: the photo paths (an index past the photos
// served, or in another spelling, is 404), the thumbnail kept at start, the larger picture decoded
// on request, and the photos' and places' descriptions in /api/config.json.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "app/serve/request_path.hpp"
#include "app/serve/serve_config.hpp"
#include "app/serve/serve_site.hpp"
#include "app/serve/served_pins.hpp"
#include "scene/pins/waypoints.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "test_support.hpp"

using namespace trailray::app::serve;
using trailray::terrain::DecodedImage;

namespace {

std::optional<PhotoRequest> photo_of(const std::string& target, std::size_t count) {
  const ParsedTarget t = parse_request_target(target);
  if (!t.ok()) return std::nullopt;
  return parse_photo_path(t.path, count);
}

// A flat colour as a JPEG file's bytes.
std::string flat_jpeg(std::uint32_t width, std::uint32_t height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  DecodedImage image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  for (std::uint32_t i = 0; i < width * height; ++i) image.samples8.insert(image.samples8.end(), {r, g, b});
  const auto bytes = trailray::terrain::encode_jpeg(image, 95);
  return {bytes.begin(), bytes.end()};
}

HttpResponse answer(const ServeSite& site, const std::string& target) {
  HttpAnswer a = answer_request(site, HttpRequest{"GET", target, "127.0.0.1"});
  if (a.now) return std::move(*a.now);
  EXPECT_TRUE(a.later) << target;
  return a.later(std::stop_token{});
}

DecodedImage decoded(const HttpResponse& r) {
  return trailray::terrain::decode_image(
      std::span(reinterpret_cast<const unsigned char*>(r.body.data()), r.body.size()));
}

}  // namespace

TEST(ServePhotoPath, NamesOnlyThePhotosServed) {
  ASSERT_TRUE(photo_of("/api/photos/0.jpg", 3));
  EXPECT_EQ(photo_of("/api/photos/2.jpg", 3)->index, 2u);
  EXPECT_FALSE(photo_of("/api/photos/2.jpg", 3)->large);
  ASSERT_TRUE(photo_of("/api/photos/1/large.jpg", 3));
  EXPECT_TRUE(photo_of("/api/photos/1/large.jpg", 3)->large);
  for (const char* target :
       {"/api/photos/3.jpg", "/api/photos/1000000000.jpg", "/api/photos/4294967296.jpg", "/api/photos/01.jpg",
        "/api/photos/+1.jpg", "/api/photos/.jpg", "/api/photos/1.png", "/api/photos/1", "/api/photos/1.jpg/",
        "/api/photos/3/large.jpg", "/api/photos/1/small.jpg", "/api/photos/1/large.jpg/x", "/api/photos",
        "/api/photos/", "/photos/1.jpg", "/api/photos/1/large.jpg/"})
    EXPECT_FALSE(photo_of(target, 3)) << target;
  EXPECT_FALSE(photo_of("/api/photos/0.jpg", 0));
}

TEST(ServePhotos, ThumbnailKeptLargerDecodedOnRequestBadIndexNotFound) {
  const trailray::test::TempFile photo("red.jpg", flat_jpeg(1600, 1200, 255, 0, 0));
  ServeSite site;
  ServedPhoto red{photo.str(), 1, {}};
  const std::string thumb = flat_jpeg(128, 96, 255, 0, 0);
  red.thumbnail.assign(thumb.begin(), thumb.end());
  site.photos.push_back(red);
  site.photos.push_back(ServedPhoto{photo.str() + ".gone", 1, {}});  // not decoded at start

  const HttpResponse small = answer(site, "/api/photos/0.jpg");
  ASSERT_EQ(small.status, 200u) << small.body;
  EXPECT_EQ(small.content_type, "image/jpeg");
  EXPECT_EQ(small.body, thumb);

  const HttpResponse large = answer(site, "/api/photos/0/large.jpg");
  ASSERT_EQ(large.status, 200u) << large.body;
  const DecodedImage big = decoded(large);
  EXPECT_EQ(big.width, static_cast<std::uint32_t>(kLargePhotoLongSidePx));
  EXPECT_EQ(big.height, 480u);
  EXPECT_GT(big.sample(320, 240, 0), 240u);
  EXPECT_LT(big.sample(320, 240, 1), 16u);

  EXPECT_EQ(answer(site, "/api/photos/1.jpg").status, 404u);        // no thumbnail
  EXPECT_EQ(answer(site, "/api/photos/1/large.jpg").status, 404u);  // the file is gone
  EXPECT_EQ(answer(site, "/api/photos/2.jpg").status, 404u);
  EXPECT_EQ(answer(site, "/api/photos/1000000000.jpg").status, 404u);
  EXPECT_EQ(answer(site, "/api/photos/1000000000/large.jpg").status, 404u);
  EXPECT_EQ(answer(site, "/api/photos/00.jpg").status, 404u);
}

TEST(ServePhotos, PhotosAndPlacesDescribedInTheConfiguration) {
  trailray::scene::Waypoint photo;
  photo.name = "DSCN0010.jpg";
  photo.lat_deg = 43.4674;
  photo.lon_deg = 11.8851;
  photo.ele_m = 290.0;
  photo.ground_m = 300.0;  // the marker never below the ground
  photo.time_unix_s = 1224685718.5;
  trailray::scene::Waypoint broken = photo;
  broken.name = "broken.jpg";
  broken.ele_m = std::numeric_limits<double>::quiet_NaN();
  broken.ground_m = std::numeric_limits<double>::quiet_NaN();
  broken.time_unix_s = std::numeric_limits<double>::quiet_NaN();
  std::vector<ServedPhoto> served(2);
  served[0].thumbnail = {0xff, 0xd8};
  const nlohmann::json photos = photos_json({photo, broken}, served);
  ASSERT_EQ(photos.size(), 2u);
  EXPECT_EQ(photos[0]["name"], "DSCN0010.jpg");
  EXPECT_DOUBLE_EQ(photos[0]["lat"].get<double>(), 43.4674);
  EXPECT_DOUBLE_EQ(photos[0]["ele"].get<double>(), 300.0);
  EXPECT_DOUBLE_EQ(photos[0]["time"].get<double>(), 1224685718.5);
  EXPECT_EQ(photos[0]["thumbnail"], "/api/photos/0.jpg");
  EXPECT_EQ(photos[0]["large"], "/api/photos/0/large.jpg");
  EXPECT_TRUE(photos[1]["thumbnail"].is_null());
  EXPECT_TRUE(photos[1]["ele"].is_null());
  EXPECT_TRUE(photos[1]["time"].is_null());

  trailray::scene::Waypoint peak;
  peak.name = "Naafkopf 2571 m";
  peak.symbol = "peak";
  peak.lat_deg = 47.0607725;
  peak.lon_deg = 9.6070544;
  peak.ele_m = 2571.0;
  peak.priority = -17429;
  const nlohmann::json places = places_json({peak});
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0]["name"], "Naafkopf 2571 m");
  EXPECT_EQ(places[0]["kind"], "peak");
  EXPECT_EQ(places[0]["priority"], -17429);
  EXPECT_DOUBLE_EQ(places[0]["ele"].get<double>(), 2571.0);
  EXPECT_TRUE(places[0]["ground"].is_null());

  const nlohmann::json config = serve_config({}, nullptr, nullptr, nlohmann::json::object(), {}, photos, places);
  EXPECT_EQ(config["photos"], photos);
  EXPECT_EQ(config["places"], places);
  EXPECT_EQ(serve_config({}, nullptr, nullptr, nlohmann::json::object())["photos"], nlohmann::json::array());
}
