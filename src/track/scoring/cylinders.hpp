#pragma once
// FAI Sporting Code 7D turnpoint cylinders (400 m): after the optimum over fixes is found, each
// turnpoint moves 400 m away from the middle of its neighbours and every leg shrinks by both
// cylinders, as the reference scorer does it (it, too, optimises on the fixes first; the result
// is therefore not the exact optimum over cylinder positions).

#include <vector>

#include "track/scoring/fixes.hpp"
#include "track/scoring/metric.hpp"
#include "track/scoring/optimise.hpp"

namespace trailray::track::scoring {

void apply_fai_cylinders(const Metric& metric, TypeResult& result);

}  // namespace trailray::track::scoring
