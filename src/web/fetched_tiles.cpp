#include "web/fetched_tiles.hpp"

#include <emscripten/fetch.h>

#include <algorithm>
#include <cstring>

namespace trailray::web {
namespace {

struct Request {
  std::shared_ptr<FetchedTiles*> source;
  terrain::TileId tile;
};

}  // namespace

FetchedTiles::FetchedTiles(terrain::SourceInfo info, std::function<void()> on_arrival, int max_in_flight,
                           std::size_t max_kept)
    : info_(std::move(info)),
      url_(info_.name),
      on_arrival_(std::move(on_arrival)),
      max_in_flight_(max_in_flight),
      max_kept_(std::max<std::size_t>(max_kept, 1)),
      self_(std::make_shared<FetchedTiles*>(this)) {}

FetchedTiles::~FetchedTiles() {
  *self_ = nullptr;  // answers still on their way find no source
  for (auto& [tile, fetch] : in_flight_) emscripten_fetch_close(fetch);
}

terrain::EncodedTile FetchedTiles::fetch(const terrain::TileId& tile, terrain::StopToken) {
  if (auto it = arrived_.find(tile); it != arrived_.end()) {
    terrain::EncodedTile out = std::move(it->second.tile);
    arrived_.erase(it);
    return out;
  }
  terrain::EncodedTile waiting;
  waiting.status = terrain::TileStatus::cancelled;
  if (in_flight_.contains(tile) || static_cast<int>(in_flight_.size()) >= max_in_flight_) return waiting;
  const terrain::ExpandedText url = url_.url_for(tile);
  if (!url.error.empty()) {
    terrain::EncodedTile failed;
    failed.status = terrain::TileStatus::failed;
    failed.error = url.error;
    return failed;
  }
  emscripten_fetch_attr_t attributes;
  emscripten_fetch_attr_init(&attributes);
  std::strcpy(attributes.requestMethod, "GET");
  attributes.attributes = EMSCRIPTEN_FETCH_LOAD_TO_MEMORY;
  attributes.onsuccess = &FetchedTiles::on_success;
  attributes.onerror = &FetchedTiles::on_error;
  attributes.userData = new Request{self_, tile};
  in_flight_[tile] = emscripten_fetch(&attributes, url.text.c_str());
  return waiting;
}

std::size_t FetchedTiles::kept_bytes() const {
  std::size_t bytes = 0;
  for (const auto& [tile, kept] : arrived_) bytes += kept.tile.bytes.size();
  return bytes;
}

void FetchedTiles::on_success(emscripten_fetch_t* fetch) {
  auto* request = static_cast<Request*>(fetch->userData);
  if (FetchedTiles* source = *request->source) source->arrived(fetch, true);
  delete request;
  emscripten_fetch_close(fetch);
}

void FetchedTiles::on_error(emscripten_fetch_t* fetch) {
  auto* request = static_cast<Request*>(fetch->userData);
  if (FetchedTiles* source = *request->source) source->arrived(fetch, false);
  delete request;
  emscripten_fetch_close(fetch);
}

void FetchedTiles::arrived(emscripten_fetch_t* fetch, bool ok) {
  const terrain::TileId tile = static_cast<Request*>(fetch->userData)->tile;
  in_flight_.erase(tile);
  // At the bound, the tile that has waited longest goes: no view took it since it came.
  if (!arrived_.contains(tile) && arrived_.size() >= max_kept_) {
    const auto oldest = std::min_element(arrived_.begin(), arrived_.end(),
                                         [](const auto& a, const auto& b) { return a.second.serial < b.second.serial; });
    arrived_.erase(oldest);
    ++dropped_;
  }
  Arrived& kept = arrived_[tile];
  kept.serial = ++arrivals_;
  terrain::EncodedTile& out = kept.tile;
  out = {};
  if (ok && fetch->status == 200) {
    out.status = terrain::TileStatus::ok;
    out.bytes.assign(fetch->data, fetch->data + fetch->numBytes);
  } else if (fetch->status == 404 || fetch->status == 204) {
    out.status = terrain::TileStatus::no_data;
  } else {
    out.status = terrain::TileStatus::failed;
    out.error = url_.display() + " " + geo::to_string(tile) + ": " +
                (fetch->status == 0 ? std::string("unreachable (network, or no CORS headers)")
                                    : "HTTP " + std::to_string(fetch->status));
  }
  if (on_arrival_) on_arrival_();
}

}  // namespace trailray::web
