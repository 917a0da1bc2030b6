#include "track/places/osm_places_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <osmium/handler.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/osm/node.hpp>
#include <osmium/osm/relation.hpp>
#include <osmium/osm/way.hpp>
#include <osmium/visitor.hpp>

#include "track/places/place_area.hpp"
#include "track/places/place_tags.hpp"

namespace trailray::track::places {

namespace {

std::string_view tag(const osmium::TagList& tags, const char* key) {
  const char* v = tags.get_value_by_key(key);
  return v != nullptr ? std::string_view(v) : std::string_view();
}

PlaceTags place_tags_of(const osmium::TagList& tags) {
  return {tag(tags, "name"), tag(tags, "natural"), tag(tags, "water"),
          tag(tags, "mountain_pass"), tag(tags, "tourism"), tag(tags, "place")};
}

Place place_of(const osmium::OSMObject& object, PlaceKind kind, char type) {
  Place p;
  p.name = tag(object.tags(), "name");
  p.kind = kind;
  p.ele_m = parse_ele(tag(object.tags(), "ele"));
  p.osm_type = type;
  p.osm_id = object.id();
  return p;
}

// A lake drawn as an area: its place (no position yet) and the ways or nodes of its ring.
struct LakeArea {
  Place place;
  std::vector<osmium::object_id_type> ids;  // a way's nodes, or a relation's outer ways
};

// Pass 1, ways and relations: the named lakes, and the node ids of the ways among them.
struct AreaPass : osmium::handler::Handler {
  std::vector<LakeArea> ways, relations;
  void way(const osmium::Way& w) {
    if (w.tags().empty() || classify_place(place_tags_of(w.tags()), true) != PlaceKind::Lake) return;
    LakeArea lake{place_of(w, PlaceKind::Lake, 'w'), {}};
    for (const osmium::NodeRef& r : w.nodes()) lake.ids.push_back(r.ref());
    if (!lake.ids.empty()) ways.push_back(std::move(lake));
  }
  void relation(const osmium::Relation& r) {
    if (r.tags().empty()) return;
    const std::string_view type = tag(r.tags(), "type");
    if (type != "multipolygon" && type != "boundary") return;
    if (classify_place(place_tags_of(r.tags()), true) != PlaceKind::Lake) return;
    LakeArea lake{place_of(r, PlaceKind::Lake, 'r'), {}};
    for (const osmium::RelationMember& m : r.members())
      if (m.type() == osmium::item_type::way && (std::string_view(m.role()) == "outer" || *m.role() == '\0'))
        lake.ids.push_back(m.ref());
    if (!lake.ids.empty()) relations.push_back(std::move(lake));
  }
};

// Pass 2 (only when a lake is a relation), ways: the nodes of the relations' outer ways.
struct MemberWayPass : osmium::handler::Handler {
  const std::unordered_set<osmium::object_id_type>* wanted = nullptr;
  std::unordered_map<osmium::object_id_type, std::vector<osmium::object_id_type>> nodes_of;
  void way(const osmium::Way& w) {
    if (wanted->count(w.id()) == 0) return;
    std::vector<osmium::object_id_type>& refs = nodes_of[w.id()];
    for (const osmium::NodeRef& r : w.nodes()) refs.push_back(r.ref());
  }
};

// Last pass, nodes: the tagged places inside the area, and the locations of the lakes' nodes.
struct NodePass : osmium::handler::Handler {
  const std::optional<geo::LatLonBounds>* bounds = nullptr;
  const std::unordered_set<osmium::object_id_type>* wanted = nullptr;
  std::vector<Place> places;
  std::unordered_map<osmium::object_id_type, osmium::Location> locations;
  void node(const osmium::Node& n) {
    const osmium::Location at = n.location();
    if (!at.valid()) return;  // a bad element: skipped
    if (!wanted->empty() && wanted->count(n.id()) != 0) locations.emplace(n.id(), at);
    if (n.tags().empty()) return;
    const double lat = at.lat_without_check(), lon = at.lon_without_check();
    if (*bounds && !contains(**bounds, lat, lon)) return;
    const std::optional<PlaceKind> kind = classify_place(place_tags_of(n.tags()), false);
    if (!kind) return;
    Place p = place_of(n, *kind, 'n');
    p.lat_deg = lat;
    p.lon_deg = lon;
    places.push_back(std::move(p));
  }
};

// A ring's label point: the mean of its nodes that have a location (a closed ring's repeated
// first node counted once). False when none has.
bool place_at_mean(Place& place, const std::vector<osmium::object_id_type>& nodes,
                   const std::unordered_map<osmium::object_id_type, osmium::Location>& locations) {
  double lat = 0, lon = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (i + 1 == nodes.size() && i > 0 && nodes[i] == nodes.front()) break;
    const auto at = locations.find(nodes[i]);
    if (at == locations.end()) continue;
    lat += at->second.lat_without_check();
    lon += at->second.lon_without_check();
    ++n;
  }
  if (n == 0) return false;
  place.lat_deg = lat / static_cast<double>(n);
  place.lon_deg = lon / static_cast<double>(n);
  return true;
}

// The passes over a file, each opened by `open` (a path or bytes in memory).
std::vector<Place> read_places(const std::function<osmium::io::File()>& open, const PlacesReadOptions& options) {
  AreaPass areas;
  {
    osmium::io::Reader reader(open(), osmium::osm_entity_bits::way | osmium::osm_entity_bits::relation);
    osmium::apply(reader, areas);
    reader.close();
  }
  std::unordered_set<osmium::object_id_type> wanted_nodes;
  for (const LakeArea& lake : areas.ways) wanted_nodes.insert(lake.ids.begin(), lake.ids.end());
  MemberWayPass members;
  std::unordered_set<osmium::object_id_type> wanted_ways;
  if (!areas.relations.empty()) {
    for (const LakeArea& lake : areas.relations) wanted_ways.insert(lake.ids.begin(), lake.ids.end());
    members.wanted = &wanted_ways;
    osmium::io::Reader reader(open(), osmium::osm_entity_bits::way);
    osmium::apply(reader, members);
    reader.close();
    for (const auto& [id, refs] : members.nodes_of) wanted_nodes.insert(refs.begin(), refs.end());
  }
  NodePass nodes;
  nodes.bounds = &options.area;
  nodes.wanted = &wanted_nodes;
  {
    osmium::io::Reader reader(open(), osmium::osm_entity_bits::node);
    osmium::apply(reader, nodes);
    reader.close();
  }
  std::vector<Place> out = std::move(nodes.places);
  const auto keep_lake = [&](Place& place, const std::vector<osmium::object_id_type>& ring) {
    if (!place_at_mean(place, ring, nodes.locations)) return;
    if (options.area && !contains(*options.area, place.lat_deg, place.lon_deg)) return;
    out.push_back(std::move(place));
  };
  for (LakeArea& lake : areas.ways) keep_lake(lake.place, lake.ids);
  for (LakeArea& lake : areas.relations) {
    std::vector<osmium::object_id_type> ring;
    for (osmium::object_id_type way : lake.ids) {
      const auto found = members.nodes_of.find(way);
      if (found != members.nodes_of.end()) ring.insert(ring.end(), found->second.begin(), found->second.end());
    }
    keep_lake(lake.place, ring);
  }
  merge_duplicate_places(out);
  return out;
}

}  // namespace

std::vector<Place> read_osm_places(const std::string& path, const PlacesReadOptions& options) {
  try {
    return read_places([&] { return osmium::io::File(path); }, options);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot read OpenStreetMap data: " + e.what());
  }
}

std::vector<Place> read_osm_places_from_memory(std::string_view bytes, const std::string& format,
                                               const std::string& name, const PlacesReadOptions& options) {
  try {
    return read_places([&] { return osmium::io::File(bytes.data(), bytes.size(), format); }, options);
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": cannot read OpenStreetMap data: " + e.what());
  }
}

}  // namespace trailray::track::places
