#!/usr/bin/python3
"""Writes trailray's two example tracks. SYNTHETIC: simulated here, not recorded by anyone.

    /usr/bin/python3 examples/make_examples.py [OUTPUT_DIR]     (default: examples/)

  paraglider_flight.igc  an afternoon paraglider flight from Amisbuehl above Interlaken
                         (Switzerland): launch, six thermals (circling climbs drifting with
                         the wind), glides with sink in between, height burned over the
                         landing field, landing on the valley floor. IGC, B records every 2 s,
                         GNSS and pressure altitude, FXA/SIU extensions.
  hike.gpx               a morning hike from Interlaken up the Harder slope (about 470 m of
                         climb), a 10-minute pause at the top, down by another path. GPX 1.1,
                         a point every 5 s with elevation, time and heart rate (Garmin
                         TrackPointExtension), a few metres of GPS noise.

Both are deterministic (fixed seeds, Python's stdlib only), so running the script again gives
byte-identical files. Both sit on the swisstopo DHM25 extract in shared/data
(dem/interlaken_dhm25_*.tif): the hike's waypoints and the launch and landing heights were
sampled from that DEM once, and are written out below, so the script needs no data.
"""

import math
import os
import random
import sys
from datetime import datetime, timedelta, timezone

CREATOR = "trailray make_examples.py (synthetic)"

# --- local tangent plane ------------------------------------------------------------------
_A = 6378137.0
_E2 = 6.69437999014e-3


class Plane:
    """East/north metres around an origin (equirectangular with WGS84 radii; fine for ~20 km)."""

    def __init__(self, lat0, lon0):
        self.lat0, self.lon0 = lat0, lon0
        s = math.sin(math.radians(lat0))
        w = 1.0 - _E2 * s * s
        self.m = _A * (1.0 - _E2) / w ** 1.5 * math.pi / 180.0  # metres per degree latitude
        self.n = _A / math.sqrt(w) * math.cos(math.radians(lat0)) * math.pi / 180.0

    def to_en(self, lat, lon):
        return ((lon - self.lon0) * self.n, (lat - self.lat0) * self.m)

    def to_ll(self, e, n):
        return (self.lat0 + n / self.m, self.lon0 + e / self.n)


class Ar1:
    """First-order autoregressive noise: standard deviation `sigma`, correlation time `tau` s."""

    def __init__(self, rng, sigma, tau, mean=0.0):
        self.rng, self.sigma, self.tau, self.mean = rng, sigma, tau, mean
        self.x = 0.0

    def step(self, dt):
        a = math.exp(-dt / self.tau)
        self.x = a * self.x + math.sqrt(1.0 - a * a) * self.sigma * self.rng.gauss(0.0, 1.0)
        return self.mean + self.x


def bearing_deg(de, dn):
    return math.degrees(math.atan2(de, dn)) % 360.0


def angle_diff(a, b):
    """a - b in degrees, wrapped into [-180, 180)."""
    return (a - b + 180.0) % 360.0 - 180.0


# --- paraglider flight (IGC) -----------------------------------------------------------------

FLIGHT_DATE = datetime(2024, 7, 14, 10, 2, 0, tzinfo=timezone.utc)  # 12:02 local (CEST)
LAUNCH = (46.71425, 7.82415, 1584.0)    # Amisbuehl; ground height from the DHM25 extract
LANDING = (46.68600, 7.85800, 569.7)    # Hoehematte, Interlaken; ground height from DHM25
WIND_FROM_DEG = 230.0                   # south-westerly valley/upper wind
QNH_OFFSET_M = -41.0                    # pressure altitude (ISA, QNH 1018 hPa) minus true altitude

# (kind, arguments): the flight plan. Thermal: top altitude (m), net climb in the core (m/s),
# turn direction (+1 right, -1 left). Glide: target (lat, lon), airspeed (m/s).
FLIGHT_PLAN = [
    ("ground", 75.0),
    ("launch", 140.0),
    ("glide", (46.70900, 7.83200), 10.0),
    ("thermal", 2450.0, 2.6, -1),
    ("glide", (46.71950, 7.87000), 10.5),
    ("thermal", 2750.0, 3.1, +1),
    ("glide", (46.72650, 7.90500), 10.0),
    ("thermal", 2850.0, 1.7, -1),
    ("glide", (46.70100, 7.85600), 11.0),
    ("thermal", 2500.0, 2.2, +1),
    ("glide", (46.70400, 7.82300), 10.5),
    ("thermal", 2650.0, 2.8, -1),
    ("glide", (46.72900, 7.84200), 10.0),
    ("thermal", 2450.0, 1.3, +1),
    ("glide", (46.71500, 7.90000), 10.5),
    ("thermal", 2600.0, 2.0, -1),
    ("glide", (46.68900, 7.85600), 11.2),
    ("burn", 180.0),            # lose height over the landing field down to this AGL
    ("land",),
    ("ground", 50.0),
]


class Glider:
    DT = 0.5  # integration step, s

    def __init__(self, rng, plane):
        self.rng, self.plane = rng, plane
        self.e, self.n = plane.to_en(LAUNCH[0], LAUNCH[1])
        self.h = LAUNCH[2]
        self.heading = 140.0
        self.airspeed = 0.0
        self.t = 0.0
        self.fixes = []  # (t, e, n, true altitude, ground speed)
        self.air = Ar1(rng, 0.55, 12.0, mean=-0.15)  # vertical air movement in glides, m/s
        self.gust = Ar1(rng, 0.25, 4.0)               # small-scale turbulence, m/s
        self.wind_var = Ar1(rng, 0.5, 120.0)
        self.on_ground = True

    def wind(self):
        speed = 2.0 + 0.0006 * max(0.0, self.h - 1000.0) + self.wind_var.x  # stronger aloft
        to = math.radians(WIND_FROM_DEG + 180.0)
        return speed * math.sin(to), speed * math.cos(to)

    def sink(self, airspeed, turning):
        # Polar of an EN-B wing: 1.1 m/s at trim (36-37 km/h), more when accelerated or banked.
        return 1.1 + 0.11 * (airspeed - 10.0) ** 2 + (0.45 if turning else 0.0)

    def advance(self, vz, move=True, ground_speed=None):
        dt = self.DT
        self.wind_var.step(dt)
        if move:
            we, wn = self.wind() if not self.on_ground else (0.0, 0.0)
            hd = math.radians(self.heading)
            ve = self.airspeed * math.sin(hd) + we
            vn = self.airspeed * math.cos(hd) + wn
            self.e += ve * dt
            self.n += vn * dt
        self.h += vz * dt
        self.t += dt
        self.fixes.append((self.t, self.e, self.n, self.h))

    def steer(self, wanted, max_rate):
        d = angle_diff(wanted, self.heading)
        step = max(-max_rate * self.DT, min(max_rate * self.DT, d))
        self.heading = (self.heading + step) % 360.0

    # phases ------------------------------------------------------------------------------
    def ground(self, seconds):
        self.on_ground = True
        self.airspeed = 0.0
        end = self.t + seconds
        while self.t < end:
            self.advance(0.0, move=False)

    def launch(self, heading):
        # Inflate, run down the launch slope (about 25 %), lift off after ~9 s.
        self.heading = heading
        t0 = self.t
        while self.t - t0 < 9.0:
            self.airspeed = min(7.5, 1.2 * (self.t - t0))
            self.advance(-0.22 * self.airspeed)
        self.on_ground = False
        while self.airspeed < 10.0:
            self.airspeed += 0.5 * self.DT
            self.advance(-self.sink(self.airspeed, False) - 0.3)

    def glide(self, target, airspeed):
        te, tn = self.plane.to_en(*target)
        wiggle = Ar1(self.rng, 6.0, 20.0)
        while True:
            de, dn = te - self.e, tn - self.n
            if math.hypot(de, dn) < 120.0:
                return
            # Crab into the wind so the ground track points at the target.
            we, wn = self.wind()
            track = math.radians(bearing_deg(de, dn))
            cross = -we * math.cos(track) + wn * math.sin(track)
            crab = math.degrees(math.asin(max(-0.9, min(0.9, cross / max(airspeed, 1.0)))))
            self.steer(bearing_deg(de, dn) + crab + wiggle.step(self.DT), 12.0)
            self.airspeed += (airspeed + 0.4 * self.gust.x - self.airspeed) * 0.1
            vz = -self.sink(self.airspeed, False) + self.air.step(self.DT) + self.gust.step(self.DT)
            self.advance(vz)

    def thermal(self, top, strength, direction):
        # Circle at 8.8-9.5 m/s with a 25-40 m radius; the thermal (and the circles) drift
        # with the wind. Climb ramps up while centring, pulses with the circle (a better
        # side), and weakens near the top.
        top += self.rng.uniform(-60.0, 60.0)
        radius = self.rng.uniform(26.0, 38.0)
        best_side = self.rng.uniform(0.0, 360.0)
        t0 = self.t
        pulse = Ar1(self.rng, 0.45, 6.0)
        while self.h < top:
            self.airspeed += (9.2 - self.airspeed) * 0.1
            rate = math.degrees(self.airspeed / radius)  # deg/s
            self.heading = (self.heading + direction * rate * self.DT) % 360.0
            ramp = min(1.0, 0.25 + (self.t - t0) / 45.0)
            taper = 1.0 - 0.6 * max(0.0, min(1.0, (self.h - (top - 300.0)) / 300.0))
            side = 0.35 * strength * math.cos(math.radians(self.heading - best_side))
            vz = max(-1.5, strength * ramp * taper + side + pulse.step(self.DT) + self.gust.step(self.DT))
            self.advance(vz)
            if self.t - t0 > 1800.0:
                break
            # Re-centre now and then: a slightly wider circle for a few seconds.
            radius = max(24.0, min(42.0, radius + self.rng.gauss(0.0, 0.4)))

    def burn(self, agl):
        # Wide figure-of-eight turns beside the landing field until `agl` above it.
        le, ln = self.plane.to_en(LANDING[0], LANDING[1])
        direction = 1
        while self.h > LANDING[2] + agl:
            t_turn = self.t
            while self.t - t_turn < 26.0 and self.h > LANDING[2] + agl:
                self.airspeed += (9.8 - self.airspeed) * 0.1
                self.heading = (self.heading + direction * math.degrees(self.airspeed / 40.0) * self.DT) % 360.0
                self.advance(-self.sink(self.airspeed, True) - 0.5 + self.air.step(self.DT) * 0.3)
            direction = -direction
            # Drift back over the field between the turns.
            t_leg = self.t
            while self.t - t_leg < 12.0 and self.h > LANDING[2] + agl:
                self.steer(bearing_deg(le - self.e, ln - self.n), 15.0)
                self.advance(-self.sink(self.airspeed, False) + self.air.step(self.DT) * 0.3)

    def land(self):
        # Downwind leg, base, final into the wind, flare, touchdown on the field.
        le, ln = self.plane.to_en(LANDING[0], LANDING[1])
        into_wind = WIND_FROM_DEG
        fin = math.radians(into_wind + 180.0)   # the final approach starts downwind of the field
        base = math.radians(into_wind + 90.0)
        legs = [
            (le + 260.0 * math.sin(fin) + 160.0 * math.sin(base), ln + 260.0 * math.cos(fin) + 160.0 * math.cos(base)),
            (le + 260.0 * math.sin(fin), ln + 260.0 * math.cos(fin)),
            (le, ln),
        ]
        for i, (te, tn) in enumerate(legs):
            while math.hypot(te - self.e, tn - self.n) > (40.0 if i < 2 else 10.0):
                self.steer(bearing_deg(te - self.e, tn - self.n), 18.0)
                height = self.h - LANDING[2]
                dist_left = math.hypot(te - self.e, tn - self.n) + sum(
                    math.hypot(legs[k + 1][0] - legs[k][0], legs[k + 1][1] - legs[k][1]) for k in range(i, 2))
                # Sink just enough to arrive at the field at ground level.
                need = height * 7.5 / max(dist_left, 1.0)
                vz = -max(0.9, min(2.6, need * 1.15))
                if height < 2.0:
                    break
                self.advance(vz)
            if self.h - LANDING[2] < 2.0:
                break
        # Flare and a few steps on the ground.
        while self.airspeed > 0.3:
            self.airspeed *= 0.8
            height = self.h - LANDING[2]
            self.advance(-min(height, 0.8) / self.DT * 0.5 if height > 0 else 0.0)
        self.h = LANDING[2]
        self.on_ground = True
        self.airspeed = 0.0


def simulate_flight(seed=20240714):
    rng = random.Random(seed)
    plane = Plane(LAUNCH[0], LAUNCH[1])
    g = Glider(rng, plane)
    for step in FLIGHT_PLAN:
        getattr(g, step[0])(*step[1:])
    return plane, g.fixes, rng


def igc_lat(lat):
    a = abs(lat)
    d = int(a)
    m = round((a - d) * 60000.0)
    if m == 60000:
        d, m = d + 1, 0
    return "%02d%05d%s" % (d, m, "N" if lat >= 0 else "S")


def igc_lon(lon):
    a = abs(lon)
    d = int(a)
    m = round((a - d) * 60000.0)
    if m == 60000:
        d, m = d + 1, 0
    return "%03d%05d%s" % (d, m, "E" if lon >= 0 else "W")


def igc_alt(h):
    h = int(round(h))
    return "%05d" % h if h >= 0 else "-%04d" % -h


def write_igc(path, seed=20240714):
    plane, fixes, rng = simulate_flight(seed)
    pos_e, pos_n = Ar1(rng, 1.4, 25.0), Ar1(rng, 1.4, 25.0)
    gnss_alt = Ar1(rng, 1.5, 30.0)
    baro = Ar1(rng, 0.25, 8.0)
    sats = 10
    lines = [
        "AXTRSYN trailray make_examples.py (synthetic)",
        "HFDTEDATE:%s,01" % FLIGHT_DATE.strftime("%d%m%y"),
        "HFFXA035",
        "HFPLTPILOTINCHARGE:Synthetic Pilot",
        "HFCM2CREW2:NIL",
        "HFGTYGLIDERTYPE:Synthetic Wing EN-B (synthetic)",
        "HFGIDGLIDERID:SYN-1",
        "HFDTMGPSDATUM:WGS84",
        "HFRFWFIRMWAREVERSION:1.0",
        "HFRHWHARDWAREVERSION:1.0",
        "HFFTYFRTYPE:" + CREATOR,
        "HFGPSRECEIVER:synthetic,simulated,12,10000",
        "HFPRSPRESSALTSENSOR:synthetic,simulated,10000",
        "HFALGALTGPS:GEO",
        "HFALPALTPRESSURE:ISA",
        "HFTZNTIMEZONE:2",
        "HFCCLCOMPETITIONCLASS:FAI-3 (PG)",
        "HOSITSITE:Amisbuehl, Interlaken (synthetic flight)",
        "I023638FXA3940SIU",
        "LXTR SYNTHETIC FLIGHT generated by trailray make_examples.py (seed %d); not a real flight" % seed,
        "LXTR launch and landing heights sampled from swisstopo DHM25; B records every 2 s",
    ]
    t0 = FLIGHT_DATE
    drift = 0.0
    for (t, e, n, h) in fixes:
        if abs(t - round(t)) > 1e-6 or int(round(t)) % 2:
            # Noise processes advance every 0.5 s step; fixes are written every 2 s.
            pos_e.step(0.5), pos_n.step(0.5), gnss_alt.step(0.5), baro.step(0.5)
            continue
        pos_e.step(0.5), pos_n.step(0.5), gnss_alt.step(0.5), baro.step(0.5)
        lat, lon = plane.to_ll(e + pos_e.x, n + pos_n.x)
        drift += 0.002 * rng.gauss(0.0, 1.0)
        p_alt = h + QNH_OFFSET_M + baro.x + drift
        g_alt = h + gnss_alt.x
        if rng.random() < 0.004:
            sats = max(6, min(12, sats + rng.choice((-1, 1))))
        fxa = max(2, min(30, int(round(4.0 + abs(pos_e.x) + abs(pos_n.x) + (12 - sats)))))
        when = t0 + timedelta(seconds=int(round(t)))
        lines.append("B%s%s%sA%s%s%03d%02d" % (when.strftime("%H%M%S"), igc_lat(lat), igc_lon(lon),
                                              igc_alt(p_alt), igc_alt(g_alt), fxa, sats))
    lines.append("LXTR end of synthetic flight")
    with open(path, "w", newline="") as f:
        f.write("\r\n".join(lines) + "\r\n")
    return len(fixes)


# --- hike (GPX) ------------------------------------------------------------------------------

HIKE_START = datetime(2024, 7, 13, 6, 48, 0, tzinfo=timezone.utc)  # 08:48 local (CEST)

# The path: Interlaken (Harderbahn valley station) up the Harder's south slope to a viewpoint
# at ~1035 m, down by a path further east, back along the valley floor. (lat, lon, ground
# height m) every 40-60 m, found once by a least-cost search on the DHM25 extract (grades
# kept walkable) and smoothed; the heights are the DEM's at those points.
HIKE_PATH = [
    (46.688990, 7.862397, 572.2),
    (46.689510, 7.862577, 575.5),
    (46.690070, 7.862937, 577.6),
    (46.690470, 7.863297, 584.7),
    (46.690750, 7.863477, 613.6),
    (46.691030, 7.863237, 624.1),
    (46.691430, 7.862877, 636.4),
    (46.691790, 7.862457, 654.0),
    (46.691990, 7.861797, 672.5),
    (46.692190, 7.861137, 689.8),
    (46.692430, 7.860777, 701.0),
    (46.692630, 7.861017, 711.6),
    (46.692870, 7.861077, 722.5),
    (46.693150, 7.860777, 743.7),
    (46.693470, 7.860897, 753.8),
    (46.693630, 7.861377, 763.5),
    (46.693750, 7.862277, 802.4),
    (46.693870, 7.862697, 805.9),
    (46.694190, 7.862457, 823.6),
    (46.694550, 7.862337, 845.4),
    (46.694910, 7.862637, 864.1),
    (46.695310, 7.863177, 872.3),
    (46.695790, 7.863717, 899.1),
    (46.696150, 7.863777, 922.7),
    (46.696350, 7.863357, 935.4),
    (46.696390, 7.862697, 944.6),
    (46.696470, 7.862337, 949.8),
    (46.696550, 7.861977, 968.3),
    (46.696550, 7.861437, 974.7),
    (46.696430, 7.860657, 982.0),
    (46.696150, 7.859637, 996.6),
    (46.695950, 7.858857, 1022.6),
    (46.695890, 7.858497, 1034.8),
    (46.696470, 7.859097, 1037.7),
    (46.696950, 7.859757, 1054.7),
    (46.697350, 7.860597, 1054.6),
    (46.697550, 7.861437, 1056.8),
    (46.697590, 7.862097, 1043.8),
    (46.697590, 7.862697, 1031.3),
    (46.697590, 7.863297, 1019.2),
    (46.697510, 7.863657, 1012.8),
    (46.697430, 7.864017, 996.0),
    (46.697510, 7.864677, 984.0),
    (46.697470, 7.865217, 963.1),
    (46.697470, 7.865817, 937.9),
    (46.697390, 7.866297, 919.9),
    (46.697390, 7.866837, 899.4),
    (46.696990, 7.866717, 888.7),
    (46.696390, 7.866297, 857.5),
    (46.695830, 7.866057, 834.8),
    (46.695270, 7.865817, 810.2),
    (46.694670, 7.865517, 785.2),
    (46.694270, 7.865517, 765.5),
    (46.693990, 7.865517, 752.3),
    (46.693590, 7.865097, 731.3),
    (46.693190, 7.864497, 712.7),
    (46.692870, 7.864137, 692.4),
    (46.692670, 7.864137, 678.1),
    (46.692670, 7.864617, 671.1),
    (46.692670, 7.865097, 650.5),
    (46.692550, 7.865277, 644.9),
    (46.692350, 7.865277, 632.3),
    (46.692230, 7.865517, 621.1),
    (46.691990, 7.865757, 607.8),
    (46.691510, 7.866117, 591.4),
    (46.690830, 7.866537, 574.2),
    (46.690230, 7.866837, 567.8),
    (46.689890, 7.866897, 567.5),
    (46.689590, 7.866897, 567.1),
    (46.689350, 7.866000, 567.2),
    (46.689150, 7.864800, 567.4),
    (46.689050, 7.863600, 567.7),
    (46.688990, 7.862397, 572.2)
]

# Stops: (fraction of the way up or down, seconds). The long one is the pause at the top.
ASCENT_STOPS = [(0.38, 60.0), (0.71, 90.0)]
TOP_PAUSE_S = 10 * 60.0
DESCENT_STOPS = [(0.55, 45.0)]


def tobler_kmh(grade):
    """Tobler's hiking function: walking speed on a slope, km/h."""
    return 6.0 * math.exp(-3.5 * abs(grade + 0.05))


def simulate_hike(seed=20240713):
    rng = random.Random(seed)
    plane = Plane(HIKE_PATH[0][0], HIKE_PATH[0][1])
    pts = [plane.to_en(la, lo) + (z,) for la, lo, z in HIKE_PATH]
    cum = [0.0]
    for a, b in zip(pts, pts[1:]):
        cum.append(cum[-1] + math.hypot(b[0] - a[0], b[1] - a[1]))
    top = max(range(len(pts)), key=lambda i: pts[i][2])
    s_top, s_end = cum[top], cum[-1]

    def at(s):
        i = 0
        while i + 1 < len(cum) - 1 and cum[i + 1] < s:
            i += 1
        seg = max(cum[i + 1] - cum[i], 1e-9)
        f = min(1.0, max(0.0, (s - cum[i]) / seg))
        a, b = pts[i], pts[i + 1]
        return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]),
                (b[2] - a[2]) / seg)

    stops = [(f * s_top, d) for f, d in ASCENT_STOPS] + [(s_top, TOP_PAUSE_S)] + \
            [(s_top + f * (s_end - s_top), d) for f, d in DESCENT_STOPS]
    pace = Ar1(rng, 0.07, 90.0, mean=1.08)  # personal factor on Tobler's speed
    dt = 1.0
    t, s = 0.0, 0.0
    samples = []  # (t, e, n, ground height, horizontal speed, vertical speed)
    standing = 30.0  # at the start: watch finds satellites, strap on
    next_stop = 0
    while True:
        e, n, z, grade = at(s)
        if standing > 0.0:
            v = 0.0
            standing -= dt
        else:
            v = tobler_kmh(grade) / 3.6 * pace.step(dt)
            if s >= s_end:
                break
        s_new = min(s_end, s + v * dt)
        if next_stop < len(stops) and s < stops[next_stop][0] <= s_new:
            s_new = stops[next_stop][0]
            standing = stops[next_stop][1] * rng.uniform(0.9, 1.1)
            next_stop += 1
        vz = (at(s_new)[2] - z) / dt
        samples.append((t, e, n, z, (s_new - s) / dt, vz))
        s = s_new
        t += dt
    samples.append((t,) + at(s_end)[:3] + (0.0, 0.0))
    return plane, samples, rng


def write_gpx(path, seed=20240713):
    plane, samples, rng = simulate_hike(seed)
    noise_e, noise_n = Ar1(rng, 2.3, 40.0), Ar1(rng, 2.3, 40.0)
    baro = Ar1(rng, 0.7, 60.0)   # barometric altimeter: smooth drift of a metre or so
    hr = 78.0
    out = []
    w = out.append
    w('<?xml version="1.0" encoding="UTF-8"?>\n')
    w('<gpx creator="%s" version="1.1"\n' % CREATOR)
    w('  xsi:schemaLocation="http://www.topografix.com/GPX/1/1 http://www.topografix.com/GPX/1/1/gpx.xsd '
      'http://www.garmin.com/xmlschemas/TrackPointExtension/v1 '
      'http://www.garmin.com/xmlschemas/TrackPointExtensionv1.xsd"\n')
    w('  xmlns:ns3="http://www.garmin.com/xmlschemas/TrackPointExtension/v1"\n')
    w('  xmlns="http://www.topografix.com/GPX/1/1"\n')
    w('  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">\n')
    w('  <metadata>\n')
    w('    <name>Synthetic hike above Interlaken</name>\n')
    w('    <desc>SYNTHETIC track generated by trailray make_examples.py (seed %d): a simulated hike, '
      'not a recording. Path and heights follow the swisstopo DHM25 terrain; speeds from '
      'Tobler\'s hiking function; GPS noise and heart rate are simulated.</desc>\n' % seed)
    w('    <author>\n      <name>%s</name>\n    </author>\n' % CREATOR)
    w('    <time>%s</time>\n' % HIKE_START.strftime("%Y-%m-%dT%H:%M:%SZ"))
    w('    <keywords>synthetic, example, trailray</keywords>\n')
    w('  </metadata>\n')
    w('  <trk>\n    <name>Harder slope hike (synthetic)</name>\n    <type>hiking</type>\n    <trkseg>\n')
    count = 0
    next_t = 0.0
    for (t, e, n, z, vh, vz) in samples:
        # Heart rate follows the effort with a lag: walking, and climbing far more.
        target = 72.0 + 24.0 * vh + 330.0 * max(vz, 0.0) + 25.0 * max(-vz, 0.0) + t / 600.0
        tau = 25.0 if target > hr else 45.0
        hr += (target - hr) * (1.0 - math.exp(-1.0 / tau))
        noise_e.step(1.0), noise_n.step(1.0), baro.step(1.0)
        if t < next_t:
            continue
        next_t = t + (5.0 if rng.random() > 0.03 else 6.0)  # now and then a second late
        lat, lon = plane.to_ll(e + noise_e.x, n + noise_n.x)
        when = HIKE_START + timedelta(seconds=int(t))
        w('      <trkpt lat="%.6f" lon="%.6f"><ele>%.1f</ele><time>%s</time><extensions>'
          '<ns3:TrackPointExtension><ns3:hr>%d</ns3:hr></ns3:TrackPointExtension>'
          '</extensions></trkpt>\n'
          % (lat, lon, z + baro.x, when.strftime("%Y-%m-%dT%H:%M:%SZ"),
             int(round(hr + rng.gauss(0.0, 1.2)))))
        count += 1
    w('    </trkseg>\n  </trk>\n</gpx>\n')
    with open(path, "w", newline="\n") as f:
        f.write("".join(out))
    return count


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(out_dir, exist_ok=True)
    igc = os.path.join(out_dir, "paraglider_flight.igc")
    gpx = os.path.join(out_dir, "hike.gpx")
    write_igc(igc)
    n = write_gpx(gpx)
    print("wrote %s (%d bytes)" % (igc, os.path.getsize(igc)))
    print("wrote %s (%d points, %d bytes)" % (gpx, n, os.path.getsize(gpx)))


if __name__ == "__main__":
    main()
