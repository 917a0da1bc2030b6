#include "terrain/sources/http_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "terrain/local_tile_server.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;
using test::http::BlackHoleServer;
using test::http::files_containing;
using test::http::LocalTileServer;
using test::http::TempFolder;

// The check the real factory does with a decoder; here: a PNG of 256 x 256.
std::optional<std::string> png_256(std::span<const unsigned char> bytes) {
  const std::optional<test::http::PngSize> size = test::http::png_size(bytes);
  if (!size) return "not a PNG";
  if (size->width != 256 || size->height != 256) {
    return "PNG of " + std::to_string(size->width) + " x " + std::to_string(size->height) + ", not 256 x 256";
  }
  return std::nullopt;
}

class HttpSourceTest : public ::testing::Test {
 protected:
  HttpSourceOptions options() {
    HttpSourceOptions o;
    o.cache.folder = cache_folder_.path();
    o.client.retry.first_delay = std::chrono::milliseconds(5);  // the policy, not the wait, is under test
    o.client.connect_timeout = std::chrono::seconds(5);
    o.client.total_timeout = std::chrono::seconds(20);
    o.validate = png_256;
    o.warn = [this](std::string message) {
      std::lock_guard lock(warnings_mutex_);
      warnings_.push_back(std::move(message));
    };
    return o;
  }
  std::string url(std::string_view route) const { return server_.url("/" + std::string(route) + "/{z}/{x}/{y}.png"); }
  std::vector<std::string> warnings() {
    std::lock_guard lock(warnings_mutex_);
    return warnings_;
  }
  std::vector<fs::path> cached_files() const { return files_containing(cache_folder_.path(), ".tile"); }

  static EncodedTile fetch(HttpTileSource& source, const TileId& tile) { return source.fetch(tile, {}); }

  TempFolder cache_folder_;
  LocalTileServer server_;
  std::mutex warnings_mutex_;
  std::vector<std::string> warnings_;
};

TEST_F(HttpSourceTest, FetchesATileStoresItAndSaysWhoItIs) {
  HttpTileSource source(url("tiles"), options());
  const TileId tile{12, 2137, 1445};
  const EncodedTile result = fetch(source, tile);
  ASSERT_EQ(result.status, TileStatus::ok) << result.error;
  EXPECT_EQ(result.bytes, server_.tile_bytes(12, 2137, 1445));
  EXPECT_EQ(server_.last_request_target(), "/tiles/12/2137/1445.png");
  EXPECT_TRUE(fs::exists(source.disk_cache()->entry_path(tile)));
  EXPECT_EQ(source.info().name, url("tiles"));
  EXPECT_EQ(source.info().format, "png");

  const std::string agent = server_.last_request_headers()["user-agent"];
  EXPECT_TRUE(agent.starts_with("trailray/")) << agent;
  EXPECT_TRUE(agent.ends_with(" (+https://github.com/trailray/trailray)")) << agent;
  EXPECT_EQ(agent, std::string(http_user_agent()));
}

TEST_F(HttpSourceTest, CorruptBytesFailAndAreNotStored) {
  HttpTileSource source(url("corrupt"), options());
  const EncodedTile result = fetch(source, TileId{10, 1, 2});
  EXPECT_EQ(result.status, TileStatus::failed);
  EXPECT_EQ(result.error, url("corrupt") + " 10/1/2: not a valid tile: not a PNG");
  EXPECT_TRUE(cached_files().empty());
  fetch(source, TileId{10, 1, 2});
  EXPECT_EQ(server_.request_count(), 2);  // nothing was remembered
}

TEST_F(HttpSourceTest, WrongTileSizeFailsAndIsNotStored) {
  HttpTileSource source(url("wrongsize"), options());
  const EncodedTile result = fetch(source, TileId{10, 1, 2});
  EXPECT_EQ(result.status, TileStatus::failed);
  EXPECT_NE(result.error.find("PNG of 100 x 37, not 256 x 256"), std::string::npos) << result.error;
  EXPECT_TRUE(cached_files().empty());
}

TEST_F(HttpSourceTest, NotFoundIsNoDataAndRemembered) {
  HttpTileSource source(url("missing"), options());
  EXPECT_EQ(fetch(source, TileId{10, 1, 2}).status, TileStatus::no_data);
  EXPECT_EQ(fetch(source, TileId{10, 1, 2}).status, TileStatus::no_data);
  EXPECT_EQ(server_.request_count(), 1);  // the negative entry answered the second time
  ASSERT_EQ(cached_files().size(), 1u);
  const std::optional<CacheEntry> entry = source.disk_cache()->read(TileId{10, 1, 2});
  ASSERT_TRUE(entry);
  EXPECT_TRUE(entry->info.no_data);
  EXPECT_EQ(entry->info.expires_at - entry->info.fetched_at, 24 * 3600);  // no caching headers: a day

  HttpTileSource empty(url("empty"), options());
  EXPECT_EQ(fetch(empty, TileId{10, 1, 2}).status, TileStatus::no_data);  // 204
}

TEST_F(HttpSourceTest, ServerErrorsTwiceThenOk) {
  server_.set_fail_count(2);
  HttpTileSource source(url("flaky"), options());
  const EncodedTile result = fetch(source, TileId{9, 3, 4});
  ASSERT_EQ(result.status, TileStatus::ok) << result.error;
  EXPECT_EQ(result.bytes, server_.tile_bytes(9, 3, 4));
  EXPECT_EQ(server_.request_count(), 3);
}

TEST_F(HttpSourceTest, ServerErrorForeverFailsAfterTheRetries) {
  HttpTileSource source(url("fail/503"), options());
  const EncodedTile result = fetch(source, TileId{9, 3, 4});
  EXPECT_EQ(result.status, TileStatus::failed);
  EXPECT_EQ(result.error, url("fail/503") + " 9/3/4: HTTP 503 after 3 retries");
  EXPECT_EQ(server_.request_count(), 4);
  EXPECT_TRUE(cached_files().empty());
}

TEST_F(HttpSourceTest, ClientErrorFailsWithoutRetrying) {
  HttpTileSource source(url("fail/403"), options());
  const EncodedTile result = fetch(source, TileId{9, 3, 4});
  EXPECT_EQ(result.status, TileStatus::failed);
  EXPECT_EQ(result.error, url("fail/403") + " 9/3/4: HTTP 403");
  EXPECT_EQ(server_.request_count(), 1);
}

TEST_F(HttpSourceTest, ServerThatNeverAnswersTimesOut) {
  BlackHoleServer black_hole;
  HttpSourceOptions o = options();
  o.client.connect_timeout = std::chrono::seconds(1);
  o.client.total_timeout = std::chrono::seconds(1);
  o.client.retry.max_retries = 1;
  const std::string source_url = black_hole.url("/{z}/{x}/{y}.png");
  HttpTileSource source(source_url, o);
  auto pending = std::async(std::launch::async, [&] { return fetch(source, TileId{5, 1, 1}); });
  // A hang would be a bug; 20 s is far above the two 1 s attempts.
  ASSERT_EQ(pending.wait_for(std::chrono::seconds(20)), std::future_status::ready);
  const EncodedTile result = pending.get();
  EXPECT_EQ(result.status, TileStatus::failed);
  EXPECT_TRUE(result.error.starts_with(source_url + " 5/1/1: ")) << result.error;
  EXPECT_NE(result.error.find("timed out"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("after 1 retry"), std::string::npos) << result.error;
}

TEST_F(HttpSourceTest, CacheFileCutShortIsRemovedAndRefetched) {
  server_.set_cache_control("max-age=3600");
  HttpTileSource source(url("tiles"), options());
  const TileId tile{11, 20, 30};
  ASSERT_EQ(fetch(source, tile).status, TileStatus::ok);
  const fs::path file = source.disk_cache()->entry_path(tile);
  fs::resize_file(file, fs::file_size(file) / 2);  // as a crash mid-write would leave it

  const EncodedTile again = fetch(source, tile);
  ASSERT_EQ(again.status, TileStatus::ok) << again.error;
  EXPECT_EQ(again.bytes, server_.tile_bytes(11, 20, 30));
  EXPECT_EQ(server_.request_count(), 2);
  EXPECT_EQ(source.disk_cache()->damaged_entries_removed(), 1u);
  const std::optional<CacheEntry> entry = source.disk_cache()->read(tile);  // whole again
  ASSERT_TRUE(entry);
  EXPECT_EQ(entry->payload, again.bytes);
}

TEST_F(HttpSourceTest, FreshEntryIsServedWithTheServerStopped) {
  server_.set_cache_control("max-age=3600");
  HttpTileSource source(url("tiles"), options());
  const EncodedTile first = fetch(source, TileId{8, 100, 90});
  ASSERT_EQ(first.status, TileStatus::ok);
  server_.stop();
  const EncodedTile second = fetch(source, TileId{8, 100, 90});
  ASSERT_EQ(second.status, TileStatus::ok) << second.error;
  EXPECT_EQ(second.bytes, first.bytes);
  EXPECT_EQ(server_.request_count(), 1);
  EXPECT_TRUE(warnings().empty());  // no network was tried, so nothing was found missing
}

TEST_F(HttpSourceTest, OfflineServesTheCacheAndNeverConnects) {
  server_.set_cache_control("no-cache");  // stored, but stale at once
  {
    HttpTileSource online(url("tiles"), options());
    ASSERT_EQ(fetch(online, TileId{8, 1, 1}).status, TileStatus::ok);
  }
  ASSERT_EQ(server_.request_count(), 1);
  HttpSourceOptions o = options();
  o.offline = true;
  HttpTileSource offline(url("tiles"), o);
  const EncodedTile cached = fetch(offline, TileId{8, 1, 1});
  ASSERT_EQ(cached.status, TileStatus::ok);  // stale is fine offline
  EXPECT_EQ(cached.bytes, server_.tile_bytes(8, 1, 1));
  EXPECT_EQ(fetch(offline, TileId{8, 1, 2}).status, TileStatus::no_data);
  EXPECT_EQ(server_.request_count(), 1);
  EXPECT_TRUE(warnings().empty());
}

TEST_F(HttpSourceTest, StaleEntryWithEtagIsRevalidated) {
  server_.set_etags(true);
  server_.set_cache_control("no-cache");
  HttpTileSource source(url("tiles"), options());
  const TileId tile{13, 4000, 3000};
  const EncodedTile first = fetch(source, tile);
  ASSERT_EQ(first.status, TileStatus::ok);
  const std::string etag = source.disk_cache()->read(tile)->info.etag;
  EXPECT_FALSE(etag.empty());

  server_.set_cache_control("max-age=3600");
  const EncodedTile second = fetch(source, tile);
  ASSERT_EQ(second.status, TileStatus::ok) << second.error;
  EXPECT_EQ(second.bytes, first.bytes);
  EXPECT_EQ(server_.not_modified_count(), 1);
  EXPECT_EQ(server_.last_request_headers()["if-none-match"], etag);

  // The 304 refreshed the entry (max-age=3600 now): the third fetch needs no request.
  EXPECT_EQ(fetch(source, tile).status, TileStatus::ok);
  EXPECT_EQ(server_.request_count(), 2);
}

TEST_F(HttpSourceTest, FreshnessComesFromMaxAgeThenExpires) {
  HttpTileSource source(url("tiles"), options());
  server_.add_tile_header("Expires", "Thu, 01 Jan 2099 00:00:00 GMT");
  ASSERT_EQ(fetch(source, TileId{7, 1, 1}).status, TileStatus::ok);
  EXPECT_EQ(source.disk_cache()->read(TileId{7, 1, 1})->info.expires_at, 4070908800);  // no Date: as given

  // The server's clock runs a day ahead: the lifetime is Expires - Date, counted from now.
  server_.add_tile_header("Date", "Wed, 31 Dec 2098 00:00:00 GMT");
  ASSERT_EQ(fetch(source, TileId{7, 1, 2}).status, TileStatus::ok);
  const CacheEntryInfo dated = source.disk_cache()->read(TileId{7, 1, 2})->info;
  EXPECT_EQ(dated.expires_at - dated.fetched_at, 24 * 3600);

  server_.set_cache_control("max-age=600");  // wins over Expires
  ASSERT_EQ(fetch(source, TileId{7, 1, 3}).status, TileStatus::ok);
  const CacheEntryInfo aged = source.disk_cache()->read(TileId{7, 1, 3})->info;
  EXPECT_EQ(aged.expires_at - aged.fetched_at, 600);
}

TEST_F(HttpSourceTest, NoStoreIsNotCached) {
  HttpTileSource source(url("nostore"), options());
  ASSERT_EQ(fetch(source, TileId{7, 1, 1}).status, TileStatus::ok);
  EXPECT_TRUE(cached_files().empty());
  ASSERT_EQ(fetch(source, TileId{7, 1, 1}).status, TileStatus::ok);
  EXPECT_EQ(server_.request_count(), 2);
}

TEST_F(HttpSourceTest, ManyThreadsShareALimitOfTwoRequests) {
  server_.set_delay(std::chrono::milliseconds(15));  // so that requests would overlap
  HttpSourceOptions o = options();
  o.client.limiter = std::make_shared<RequestLimiter>(2);
  HttpTileSource source(url("tiles"), o);
  std::vector<std::thread> threads;
  std::atomic<int> ok{0}, wrong{0};
  for (std::uint32_t t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      for (std::uint32_t i = 0; i < 8; ++i) {
        const EncodedTile result = fetch(source, TileId{10, t, i});
        const bool right = result.status == TileStatus::ok && result.bytes == server_.tile_bytes(10, t, i);
        (right ? ok : wrong)++;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(ok, 64);
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(server_.request_count(), 64);
  EXPECT_LE(server_.max_concurrency(), 2);
  EXPECT_EQ(o.client.limiter->in_use(), 0);
  EXPECT_EQ(cached_files().size(), 64u);
  EXPECT_TRUE(files_containing(cache_folder_.path(), ".tmp-").empty());  // every write renamed
}

TEST_F(HttpSourceTest, OneFailingTileDoesNotAffectTheOthers) {
  TempFolder tiles;
  LocalTileServer folder_server(tiles.path());
  for (std::uint32_t x = 0; x < 4; ++x) {
    fs::create_directories(tiles.path() / "6" / std::to_string(x));
    std::ofstream out(tiles.path() / "6" / std::to_string(x) / "9.png", std::ios::binary);
    const std::vector<unsigned char> png = test::http::make_png(256, 256, x);
    if (x == 2) {
      out << "truncated";
    } else {
      out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    }
  }
  HttpTileSource source(folder_server.url("/tiles/{z}/{x}/{y}.png"), options());
  std::vector<std::future<EncodedTile>> results;
  for (std::uint32_t x = 0; x < 5; ++x) {
    results.push_back(std::async(std::launch::async, [&source, x] { return fetch(source, TileId{6, x, 9}); }));
  }
  EXPECT_EQ(results[0].get().status, TileStatus::ok);
  EXPECT_EQ(results[1].get().status, TileStatus::ok);
  const EncodedTile broken = results[2].get();
  EXPECT_EQ(broken.status, TileStatus::failed);
  EXPECT_NE(broken.error.find(" 6/2/9: not a valid tile"), std::string::npos) << broken.error;
  EXPECT_EQ(results[3].get().status, TileStatus::ok);
  EXPECT_EQ(results[4].get().status, TileStatus::no_data);  // no file: 404
  EXPECT_EQ(fetch(source, TileId{6, 3, 9}).bytes, test::http::make_png(256, 256, 3));
}

TEST_F(HttpSourceTest, SecretsReachTheServerButNoMessage) {
  const std::string secret = "sk-TOPSECRET-4242";
  ::setenv("TRAILRAY_TEST_TILE_KEY", secret.c_str(), 1);
  HttpSourceOptions o = options();
  o.client.headers = {{"X-Api-Key", "${TRAILRAY_TEST_TILE_KEY}"}, {"Accept", "image/png"}};
  o.client.retry.max_retries = 1;
  const std::string source_url = server_.url("/fail/503/{z}/{x}/{y}.png?key=${TRAILRAY_TEST_TILE_KEY}");
  HttpTileSource source(source_url, o);

  const EncodedTile failed = fetch(source, TileId{4, 3, 2});
  EXPECT_EQ(failed.status, TileStatus::failed);
  EXPECT_EQ(server_.last_request_headers()["x-api-key"], secret);
  EXPECT_EQ(server_.last_request_headers()["accept"], "image/png");
  EXPECT_EQ(server_.last_request_target(), "/fail/503/4/3/2.png?key=" + secret);
  EXPECT_EQ(failed.error, source_url + " 4/3/2: HTTP 503 after 1 retry");

  server_.stop();  // now a transport error, and the unreachable warning
  const EncodedTile unreachable = fetch(source, TileId{4, 3, 3});
  EXPECT_EQ(unreachable.status, TileStatus::failed);
  const std::vector<std::string> warned = warnings();
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_TRUE(warned[0].starts_with(source_url + ": server unreachable")) << warned[0];

  for (const std::string& text : {failed.error, unreachable.error, warned[0], source.info().name,
                                  source.disk_cache()->namespace_folder().string()}) {
    EXPECT_EQ(text.find(secret), std::string::npos) << text;
    EXPECT_EQ(text.find("TOPSECRET"), std::string::npos) << text;
  }
  ::unsetenv("TRAILRAY_TEST_TILE_KEY");
  const EncodedTile unset = fetch(source, TileId{4, 3, 4});
  EXPECT_EQ(unset.status, TileStatus::failed);
  EXPECT_NE(unset.error.find("environment variable TRAILRAY_TEST_TILE_KEY is not set"), std::string::npos)
      << unset.error;
}

TEST_F(HttpSourceTest, UnreachableServerWarnsOnceAndServesStaleTiles) {
  server_.set_cache_control("no-cache");  // cached but stale: every use asks the server
  HttpSourceOptions o = options();
  HttpTileSource source(url("tiles"), o);
  ASSERT_EQ(fetch(source, TileId{9, 1, 1}).status, TileStatus::ok);
  ASSERT_EQ(fetch(source, TileId{9, 1, 2}).status, TileStatus::ok);
  server_.stop();

  const EncodedTile stale = fetch(source, TileId{9, 1, 1});
  ASSERT_EQ(stale.status, TileStatus::ok) << stale.error;
  EXPECT_EQ(stale.bytes, server_.tile_bytes(9, 1, 1));
  EXPECT_EQ(fetch(source, TileId{9, 1, 2}).status, TileStatus::ok);
  const EncodedTile missing = fetch(source, TileId{9, 1, 3});
  EXPECT_EQ(missing.status, TileStatus::failed);
  EXPECT_NE(missing.error.find("server unreachable"), std::string::npos) << missing.error;
  const std::vector<std::string> warned = warnings();
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("server unreachable"), std::string::npos) << warned[0];
}

TEST_F(HttpSourceTest, StopTokenCancelsASlowRequest) {
  HttpTileSource source(url("slow"), options());  // total timeout 20 s
  std::stop_source stop;
  auto pending = std::async(std::launch::async, [&] { return source.fetch(TileId{6, 6, 6}, stop.get_token()); });
  for (int i = 0; i < 1000 && server_.request_count() == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(server_.request_count(), 1);  // the request is in the server, waiting
  stop.request_stop();
  // Cancelling must not wait for the 20 s timeout; 10 s is a generous bound for "at once".
  ASSERT_EQ(pending.wait_for(std::chrono::seconds(10)), std::future_status::ready);
  EXPECT_EQ(pending.get().status, TileStatus::cancelled);
  EXPECT_TRUE(cached_files().empty());
  EXPECT_EQ(server_.request_count(), 1);  // a cancelled request is not retried
}

TEST_F(HttpSourceTest, ZoomOutsideTheSourceRangeIsNoDataWithoutARequest) {
  HttpSourceOptions o = options();
  o.info.min_zoom = 2;
  o.info.max_zoom = 14;
  HttpTileSource source(url("tiles"), o);
  EXPECT_EQ(fetch(source, TileId{15, 0, 0}).status, TileStatus::no_data);
  EXPECT_EQ(fetch(source, TileId{1, 0, 0}).status, TileStatus::no_data);
  EXPECT_EQ(fetch(source, TileId{3, 9, 0}).status, TileStatus::failed);  // not a tile at all
  EXPECT_EQ(server_.request_count(), 0);
}

TEST_F(HttpSourceTest, UnwritableCacheFolderFetchesWithoutCaching) {
  HttpSourceOptions o = options();
  std::ofstream(cache_folder_.path() / "file") << "in the way";
  o.cache.folder = cache_folder_.path() / "file" / "tiles";
  HttpTileSource source(url("tiles"), o);
  EXPECT_EQ(source.disk_cache(), nullptr);
  EXPECT_EQ(fetch(source, TileId{5, 5, 5}).status, TileStatus::ok);
  EXPECT_EQ(fetch(source, TileId{5, 5, 6}).status, TileStatus::ok);
  const std::vector<std::string> warned = warnings();
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_TRUE(warned[0].starts_with(url("tiles") + ": tiles are not cached (tile cache ")) << warned[0];
}

TEST_F(HttpSourceTest, BadTemplateIsASourceError) {
  EXPECT_THROW(HttpTileSource(server_.url("/tiles/{z}/{x}.png"), options()), SourceError);
}

TEST(HttpClient, ParsesCacheControl) {
  const CacheControl plain = parse_cache_control("public, max-age=86400");
  EXPECT_EQ(plain.max_age_s, 86400);
  EXPECT_FALSE(plain.no_store);
  EXPECT_FALSE(plain.no_cache);
  const CacheControl mixed = parse_cache_control("No-Cache, MAX-AGE=\"60\", no-store");
  EXPECT_TRUE(mixed.no_cache);
  EXPECT_TRUE(mixed.no_store);
  EXPECT_EQ(mixed.max_age_s, 60);
  EXPECT_EQ(parse_cache_control("max-age=soon").max_age_s, 0);  // unreadable: stale
  EXPECT_FALSE(parse_cache_control("").max_age_s);
  EXPECT_TRUE(parse_cache_control("private, no-cache=\"Set-Cookie\"").no_cache);
}

TEST(HttpClient, LimiterWaitEndsWithTheStopToken) {
  RequestLimiter limiter(1);
  ASSERT_TRUE(limiter.acquire({}));
  std::stop_source stop;
  auto waiting = std::async(std::launch::async, [&] { return limiter.acquire(stop.get_token()); });
  EXPECT_EQ(waiting.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout);  // no slot free
  stop.request_stop();
  ASSERT_EQ(waiting.wait_for(std::chrono::seconds(10)), std::future_status::ready);
  EXPECT_FALSE(waiting.get());
  EXPECT_EQ(limiter.in_use(), 1);
  limiter.release();
  EXPECT_TRUE(limiter.acquire({}));
}

}  // namespace
}  // namespace trailray::terrain
