#pragma once
// Tiles over the network in the page: the browser's fetch (Emscripten's emscripten_fetch), which
// obeys CORS and the browser's HTTP cache. The page has no threads, so fetch() never waits: a
// tile not yet here starts its request and answers "cancelled" (the tile loader asks again on a
// later frame, terrain/loading/tile_loader.hpp); once the bytes arrive `on_arrival` is called (the viewer
// draws again) and the next fetch() hands them over. 404 is "no data"; other failures carry
// the status. Requests in flight are bounded (`max_in_flight`); the others wait their turn. The
// bound is above the browser's six connections a host: requests wait in the browser's queue, not
// for the next frame to start them (a frame takes a second in software GL).
//
// A tile that arrives after the view moved on is never asked for again: arrived tiles waiting to
// be taken are bounded (`max_kept`), the oldest arrival let go first, so a long session's memory
// does not grow with every place the view passed. The loader takes a wanted tile at the frame its
// arrival asks for (a few at most arrive between two frames: those in flight), so only tiles no
// view wants reach the bound; one let go that is wanted after all is simply asked for again.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>

#include "terrain/sources/tile_source.hpp"
#include "terrain/sources/url_template.hpp"

struct emscripten_fetch_t;

namespace trailray::web {

class FetchedTiles : public terrain::EncodedTileSource {
 public:
  FetchedTiles(terrain::SourceInfo info, std::function<void()> on_arrival, int max_in_flight = 16,
               std::size_t max_kept = 64);
  ~FetchedTiles() override;
  FetchedTiles(const FetchedTiles&) = delete;
  FetchedTiles& operator=(const FetchedTiles&) = delete;

  const terrain::SourceInfo& info() const override { return info_; }
  terrain::EncodedTile fetch(const terrain::TileId& tile, terrain::StopToken stop) override;

  std::size_t in_flight() const { return in_flight_.size(); }
  // Tiles that arrived and wait for the loader to take them, and their bytes.
  std::size_t kept() const { return arrived_.size(); }
  std::size_t kept_bytes() const;
  std::size_t dropped() const { return dropped_; }  // arrived tiles let go at the bound, in all

 private:
  static void on_success(emscripten_fetch_t* fetch);
  static void on_error(emscripten_fetch_t* fetch);
  void arrived(emscripten_fetch_t* fetch, bool ok);

  terrain::SourceInfo info_;
  terrain::UrlTemplate url_;
  std::function<void()> on_arrival_;
  int max_in_flight_;
  std::size_t max_kept_;
  std::unordered_map<terrain::TileId, emscripten_fetch_t*> in_flight_;
  struct Arrived {
    terrain::EncodedTile tile;
    std::uint64_t serial = 0;  // arrival order: the oldest goes first at the bound
  };
  std::unordered_map<terrain::TileId, Arrived> arrived_;
  std::uint64_t arrivals_ = 0;
  std::size_t dropped_ = 0;
  // Each request's user data: the source, while it lives (cleared when it goes first).
  std::shared_ptr<FetchedTiles*> self_;
};

}  // namespace trailray::web
