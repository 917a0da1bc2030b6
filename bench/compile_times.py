#!/usr/bin/env python3
"""Compile every translation unit of a build tree once, without the compiler
cache, and print the seconds spent per source folder.

Why: the Release build is the largest stage of CI; this says which rooms of
src/ its time goes to (for example, how much app/ costs for its lines).
Usage: bench/compile_times.py BUILD_DIR [--jobs N] [--under src/]
"""
import argparse, collections, concurrent.futures, json, os, shlex, subprocess, tempfile, time


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--under", default="src/", help="only sources under this folder")
    ap.add_argument("--depth", type=int, default=2, help="folder depth to sum by")
    args = ap.parse_args()
    root = os.path.dirname(os.path.abspath(__file__)).rsplit("/bench", 1)[0]
    entries = json.load(open(os.path.join(args.build_dir, "compile_commands.json")))
    chosen = []
    for e in entries:
        rel = os.path.relpath(e["file"], root)
        if rel.startswith(args.under):
            chosen.append((rel, e))
    out_dir = tempfile.mkdtemp(prefix="compile_times.")

    def compile_one(item):
        rel, e = item
        words = shlex.split(e["command"]) if "command" in e else e["arguments"]
        if "ccache" in os.path.basename(words[0]):
            words = words[1:]
        o = words.index("-o")
        words[o + 1] = os.path.join(out_dir, str(abs(hash(rel))) + ".o")
        start = time.monotonic()
        subprocess.run(words, cwd=e["directory"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return rel, time.monotonic() - start

    per_file = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for rel, seconds in pool.map(compile_one, chosen):
            per_file[rel] = seconds
    folders = collections.Counter()
    counts = collections.Counter()
    for rel, s in per_file.items():
        key = "/".join(rel.split("/")[:args.depth])
        folders[key] += s
        counts[key] += 1
    total = sum(per_file.values())
    print(f"{len(per_file)} translation units, {total:.0f} s of compiler time in all")
    for key, s in folders.most_common():
        print(f"{key:28s} {counts[key]:4d} files {s:8.1f} s {100 * s / total:5.1f} %")
    print("slowest files:")
    for rel, s in sorted(per_file.items(), key=lambda kv: -kv[1])[:15]:
        print(f"  {s:6.1f} s  {rel}")


if __name__ == "__main__":
    main()
