#pragma once
// The output of `trailray score`: one JSON document or a readable table.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "track/scoring/score.hpp"

namespace trailray::app {

nlohmann::json score_json(const track::scoring::ScoreResult& r, const std::vector<track::scoring::Fix>& fixes);
std::string score_table(const track::scoring::ScoreResult& r, const std::vector<track::scoring::Fix>& fixes);

}  // namespace trailray::app
