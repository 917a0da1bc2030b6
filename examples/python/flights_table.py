"""One row per track of every track file in a folder, sorted by XC score, and a picture of the best.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/flights_table.py [FOLDER] [OUT.png]
"""
import math
import sys
import warnings
from pathlib import Path

import pandas as pd
import trailray

ROOT = Path(__file__).resolve().parents[2]
SHARED_IGC = ROOT.parent / "shared" / "data" / "igc"
# The extensions the command line takes from a folder; each may also end in .gz.
TRACK_EXTENSIONS = {".gpx", ".igc", ".tcx", ".fit", ".kml", ".kmz", ".geojson", ".json"}


def is_track_file(path):
    name = path.name.lower().removesuffix(".gz")
    return path.is_file() and Path(name).suffix in TRACK_EXTENSIONS


def number(value):
    """A statistic as a float: the statistics say None where a track cannot tell (no times...)."""
    return math.nan if value is None else float(value)


def main():
    folder = Path(sys.argv[1]) if len(sys.argv) > 1 else (SHARED_IGC if SHARED_IGC.is_dir() else ROOT / "examples")
    picture_path = Path(sys.argv[2]) if len(sys.argv) > 2 else Path("out/best_flight.png")

    rows, tracks, warning_count = [], [], 0
    for path in sorted(filter(is_track_file, folder.iterdir())):
        # Reader warnings (a bad line skipped...) would print between the rows; File.warnings
        # keeps them, so they are only counted.
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", trailray.TrailrayWarning)
            try:
                file = trailray.read(path)
            except trailray.ReadError as error:
                print(f"skipped: {error}")
                continue
        warning_count += len(file.warnings)
        for track in file.tracks:
            clean = track.stats()["clean"]
            rows.append({
                "file": path.name,
                "track": track.name,
                "points": len(track),
                "distance_km": number(clean["distance_2d_m"]) / 1000,
                "duration_h": number(clean["duration_s"]) / 3600,
                "gain_m": number(clean["elevation_gain_m"]),
                "max_climb_ms": number(clean["max_climb_ms"]),
                # XC scoring rules are for flights: only IGC files get a score.
                "score": trailray.score(track)["score"] if file.format == "igc" else math.nan,
            })
            tracks.append(track)
    if not rows:
        sys.exit(f"no track in {folder}")

    table = pd.DataFrame(rows).sort_values(["score", "distance_km"], ascending=False, na_position="last")
    print(table.to_string(index=False, float_format="{:.1f}".format))
    print(f"{len(table)} tracks; reader warnings not shown: {warning_count} (File.warnings has them)")

    best = tracks[table.index[0]]  # sorting keeps each row's index: its place in tracks
    # terrain=None (a neutral ground) is chosen here, so the renderer's warning about it is noise.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        picture = trailray.render(best, size=(1280, 720), color_by="vspeed")
    picture_path.parent.mkdir(parents=True, exist_ok=True)
    picture_path.write_bytes(trailray.png(picture))
    print(f"best: {best.name} ({table.iloc[0]['file']}) -> {picture_path}")


if __name__ == "__main__":
    main()
