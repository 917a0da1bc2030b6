#!/usr/bin/env python3
"""Writes a big OpenStreetMap file for bench/places_read.sh: COPIES copies of a real extract, each
with its ids moved past the others' and shifted east by 0.5 degree a copy, so nothing repeats.
The copies go through `osmium cat` as OPL and come out as a sorted .osm.pbf (osmium-tool, Debian),
renumbered 1, 2, 3, ... as a real extract's ids are dense.

    make_big_osm.py SOURCE.osm.pbf OUT.osm.pbf [--copies N]
"""
import argparse
import os
import subprocess
import sys


def shifted(line, k, id_step, lon_step):
    out = []
    for field in line.rstrip("\n").split(" "):
        tag, value = field[:1], field[1:]
        if tag in "nwr" and not out:
            field = tag + str(int(value) + k * id_step)
        elif tag == "x" and value:
            field = "x%.7f" % (float(value) + k * lon_step)
        elif tag == "N" and value:
            field = "N" + ",".join("n%d" % (int(ref[1:]) + k * id_step) for ref in value.split(","))
        elif tag == "M" and value:
            members = []
            for m in value.split(","):
                ref, _, role = m.partition("@")
                members.append("%s%d@%s" % (ref[0], int(ref[1:]) + k * id_step, role))
            field = "M" + ",".join(members)
        out.append(field)
    return " ".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("source")
    parser.add_argument("out")
    parser.add_argument("--copies", type=int, default=32)
    args = parser.parse_args()
    lines = subprocess.run(["osmium", "cat", "-f", "opl", args.source, "-o", "-"], check=True,
                           capture_output=True, text=True).stdout.splitlines(keepends=True)
    id_step = 20_000_000_000
    # Nodes of every copy first, then ways, then relations: the order a PBF needs.
    writer = subprocess.Popen(["osmium", "cat", "-F", "opl", "-", "-o", args.out, "--overwrite",
                               "-f", "pbf"], stdin=subprocess.PIPE, text=True)
    for kind in "nwr":
        for k in range(args.copies):
            writer.stdin.writelines(shifted(l, k, id_step, 0.5) for l in lines if l.startswith(kind))
    writer.stdin.close()
    if writer.wait() != 0:
        return 1
    # Ids 1, 2, 3, ... as in a real extract: the copies' ids moved by 2e10 each would make
    # osmium's id sets (tags-filter keeps the nodes the ways it keeps use) gigabytes.
    subprocess.run(["osmium", "renumber", args.out, "-o", args.out + ".renumbered.osm.pbf", "--overwrite"], check=True)
    os.replace(args.out + ".renumbered.osm.pbf", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
