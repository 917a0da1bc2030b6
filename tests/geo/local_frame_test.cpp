#include "geo/local_frame.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace trailray::geo {
namespace {

double metres_between(double lat1, double lon1, double lat2, double lon2) {
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s12);
  return s12;
}

double wrapped(double lon) { return lon > 180.0 ? lon - 360.0 : lon < -180.0 ? lon + 360.0 : lon; }

struct Cluster {
  double lat0 = 0.0, lon0 = 0.0;
  std::vector<double> a, b, w;  // offsets from (lat0, lon0) in degrees, weights
};

// The exact weighted 3D mean of the cluster, projected back onto the ellipsoid.
void exact_mean(const Cluster& c, double& lat, double& lon) {
  glm::dvec3 sum{};
  double wsum = 0.0;
  for (std::size_t j = 0; j < c.a.size(); ++j) {
    const glm::dvec3 p = ecef_from_geodetic(c.lat0 + c.a[j], c.lon0 + c.b[j], 0.0);
    sum.x += c.w[j] * p.x;
    sum.y += c.w[j] * p.y;
    sum.z += c.w[j] * p.z;
    wsum += c.w[j];
  }
  sum.x /= wsum;
  sum.y /= wsum;
  sum.z /= wsum;
  const Geodetic g = geodetic_from_ecef(sum);
  lat = g.lat_deg;
  lon = g.lon_deg;
}

// The closed form from the weighted moments.
void closed_form_mean(const Cluster& c, double& lat, double& lon) {
  double w = 0.0, sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
  for (std::size_t j = 0; j < c.a.size(); ++j) {
    w += c.w[j];
    sa += c.w[j] * c.a[j];
    sb += c.w[j] * c.b[j];
    saa += c.w[j] * c.a[j] * c.a[j];
    sbb += c.w[j] * c.b[j] * c.b[j];
    sab += c.w[j] * c.a[j] * c.b[j];
  }
  const double ma = sa / w, mb = sb / w;
  const LatLonOffset o = local_mean_offset(c.lat0, ma, mb, saa / w - ma * ma, sbb / w - mb * mb, sab / w - ma * mb);
  lat = c.lat0 + o.dlat;
  lon = wrapped(c.lon0 + o.dlon);
}

// 11 points along a random path (a smoothing window: Gaussian weights, sigma 1 point) whose
// offsets from the centre point stay within `reach` degrees.
Cluster random_window(std::mt19937_64& rng, double lat0, double lon0, double reach) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Cluster c;
  c.lat0 = lat0;
  c.lon0 = lon0;
  // Steps of at most reach / 5 in each coordinate: 5 steps either side stay within reach.
  double a = 0.0, b = 0.0;
  std::vector<double> fa{0.0}, fb{0.0}, ba{}, bb{};
  for (int j = 0; j < 5; ++j) {
    a += u(rng) * reach / 5.0;
    b += u(rng) * reach / 5.0;
    fa.push_back(a);
    fb.push_back(b);
  }
  a = b = 0.0;
  for (int j = 0; j < 5; ++j) {
    a += u(rng) * reach / 5.0;
    b += u(rng) * reach / 5.0;
    ba.push_back(a);
    bb.push_back(b);
  }
  for (int j = 4; j >= 0; --j) {
    c.a.push_back(ba[j]);
    c.b.push_back(bb[j]);
  }
  c.a.insert(c.a.end(), fa.begin(), fa.end());
  c.b.insert(c.b.end(), fb.begin(), fb.end());
  for (int j = -5; j <= 5; ++j) c.w.push_back(std::exp(-0.5 * j * j));
  return c;
}

TEST(LocalMeanOffset, WithinATenthOfAMillimetreOfTheExact3DMean) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0, worst_first_order = 0.0;
  for (int k = 0; k < 40000; ++k) {
    double lat0 = (2.0 * u(rng) - 1.0) * kLocalMeanMaxLatDeg;
    if (k % 4 == 1) lat0 = (u(rng) < 0.5 ? -1.0 : 1.0) * (kLocalMeanMaxLatDeg - u(rng));  // near a pole
    double lon0 = (2.0 * u(rng) - 1.0) * 180.0;
    if (k % 4 == 2) lon0 = u(rng) < 0.5 ? 180.0 - 0.01 * u(rng) : -180.0 + 0.01 * u(rng);  // antimeridian
    const double reach = kLocalMeanMaxOffsetDeg * (k % 3 == 0 ? u(rng) : 1.0);
    const Cluster c = random_window(rng, lat0, lon0, reach);
    double lat_exact = 0.0, lon_exact = 0.0, lat = 0.0, lon = 0.0;
    exact_mean(c, lat_exact, lon_exact);
    closed_form_mean(c, lat, lon);
    const double err = metres_between(lat_exact, lon_exact, lat, lon);
    ASSERT_LT(err, 1e-4) << lat0 << " " << lon0 << " reach " << reach;
    worst = std::max(worst, err);
    // Without the second-order terms the mean is off by far more: they matter.
    double w = 0.0, sa = 0.0, sb = 0.0;
    for (std::size_t j = 0; j < c.a.size(); ++j) {
      w += c.w[j];
      sa += c.w[j] * c.a[j];
      sb += c.w[j] * c.b[j];
    }
    worst_first_order =
        std::max(worst_first_order, metres_between(lat_exact, lon_exact, lat0 + sa / w, wrapped(lon0 + sb / w)));
  }
  EXPECT_LT(worst, 4e-5);  // the figure in local_frame.hpp: 0.04 mm
  EXPECT_GT(worst_first_order, 100.0 * worst);
}

TEST(LocalMeanOffset, APointAloneIsItself) {
  const LatLonOffset o = local_mean_offset(46.5, 0.0, 0.0, 0.0, 0.0, 0.0);
  EXPECT_EQ(o.dlat, 0.0);
  EXPECT_EQ(o.dlon, 0.0);
}

TEST(Ecef, RoundTrip) {
  for (double lat : {-90.0, -45.0, 0.0, 46.5, 89.999}) {
    for (double lon : {-180.0, -7.5, 0.0, 179.999}) {
      const Geodetic back = geodetic_from_ecef(ecef_from_geodetic(lat, lon, 0.0));
      EXPECT_NEAR(back.lat_deg, lat, 1e-12);
      if (std::abs(lat) < 90.0) {
        EXPECT_NEAR(std::remainder(back.lon_deg - lon, 360.0), 0.0, 1e-12);
      }
    }
  }
}

}  // namespace
}  // namespace trailray::geo
