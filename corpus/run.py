#!/usr/bin/env python3
"""Run curvekit on every file of a corpus and judge each answer with the independent oracle.

    python corpus/run.py CORPUS_DIR [--bin PATH] [--jobs 2] [--report report.json] [--only GLOB]

CORPUS_DIR holds manifest.json (as gather.py writes it); the binary is --bin, else
$CURVEKIT_BIN, else target/release/curvekit. Prints a table per source and command (answered,
refused with the message patterns, wrong answers, crashes, time-outs) and the reading speed, and
writes every outcome to the JSON report.
"""

from __future__ import annotations

import argparse
import dataclasses
import fnmatch
import json
import os
import sys
import time
from collections import Counter, defaultdict
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from oracle import judge_file, message_pattern  # noqa: E402

COLUMNS = ["answered", "refused", "refused-valid", "refused-wrong-cause", "answered-invalid",
           "wrong-certified", "wrong-uncertified", "crash", "timeout", "oracle-error"]


def judge_entry(binary: str, root: str, entry: dict) -> list[dict]:
    outcomes = judge_file(binary, str(Path(root) / entry["file"]), entry.get("expect"))
    return [dict(dataclasses.asdict(o), file=entry["file"], source=entry["source"]) for o in outcomes]


def judge_corpus(binary: str, root: Path, entries: list[dict], jobs: int, progress: bool = True) -> list[dict]:
    outcomes = []
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(judge_entry, binary, str(root), e): e for e in entries}
        for done, future in enumerate(as_completed(futures), 1):
            outcomes.extend(future.result())
            if progress:
                print(f"\r{done}/{len(entries)} files", end="", file=sys.stderr, flush=True)
    if progress:
        print(file=sys.stderr)
    order = {e["file"]: i for i, e in enumerate(entries)}
    return sorted(outcomes, key=lambda o: (order[o["file"]], o["command"], o.get("figures", {}).get("pick", -1)))


def summary(outcomes: list[dict], root: Path, entries: list[dict]) -> str:
    lines = []
    table = defaultdict(Counter)
    certified = Counter()
    for o in outcomes:
        table[(o["source"], o["command"])][o["status"]] += 1
        if o["status"] == "answered":
            certified[(o["source"], o["command"])] += bool(o["certified"])
    head = f"{'source':<18} {'command':<14}" + "".join(f"{c[:12]:>13}" for c in COLUMNS) + "   certified"
    lines.append(head)
    totals = defaultdict(Counter)
    for (source, command), counts in sorted(table.items()):
        lines.append(f"{source:<18} {command:<14}" + "".join(f"{counts[c]:>13}" for c in COLUMNS) + f"   {certified[(source, command)]:>9}")
        totals[command].update(counts)
        totals[command]["certified"] += certified[(source, command)]
    lines.append("-" * len(head))
    for command, counts in sorted(totals.items()):
        lines.append(f"{'ALL':<18} {command:<14}" + "".join(f"{counts[c]:>13}" for c in COLUMNS) + f"   {counts['certified']:>9}")
    patterns = defaultdict(Counter)
    for o in outcomes:
        if o["status"].startswith("refused") or o["status"] in ("crash",):
            patterns[(o["command"], o["status"])][message_pattern(o["message"])] += 1
    lines.append("\nRefusals and crashes by message (command, status: count  pattern):")
    for (command, status), counts in sorted(patterns.items()):
        lines.append(f"  {command} [{status}]")
        for pattern, count in counts.most_common(12):
            lines.append(f"    {count:>4}  {pattern}")
    problems = Counter()
    for o in outcomes:
        if o["status"].startswith("wrong") or o["status"] == "answered-invalid":
            for p in o["problems"][:1]:
                problems[(o["command"], o["status"], problem_kind(p))] += 1
    lines.append("\nWrong answers by kind (command, status, first problem's kind: count):")
    for (command, status, kind), count in sorted(problems.items()):
        lines.append(f"  {count:>4}  {command} [{status}] {kind}")
    notes = Counter(n for o in outcomes for n in set(o["notes"]))
    lines.append("\nContract notes (outcomes carrying each):")
    for note, count in notes.most_common(10):
        lines.append(f"  {count:>4}  {note}")
    lines.append("\n" + reading_speed(outcomes, root, entries))
    return "\n".join(lines)


def problem_kind(problem: str) -> str:
    """A problem's message without its numbers, points and loop indices."""
    import re

    text = re.sub(r"\([^)]*\)", "(..)", problem)
    text = re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "N", text)
    return text[:100]


def reading_speed(outcomes: list[dict], root: Path, entries: list[dict]) -> str:
    """Wall time of the cheapest command (inflections, else the medial axis) per MB of input,
    process start included."""
    sizes = {e["file"]: (root / e["file"]).stat().st_size for e in entries}
    per_file = {}
    for o in outcomes:
        if o["command"] in ("inflections", "medial") and o["status"] != "timeout":
            if o["file"] not in per_file or o["command"] == "inflections":
                per_file[o["file"]] = o["wall"]
    rows = []
    for suffix in (".svg", ".dxf"):
        files = [f for f in per_file if f.endswith(suffix)]
        megabytes = sum(sizes[f] for f in files) / 1e6
        wall = sum(per_file[f] for f in files)
        if files:
            rows.append(f"{suffix[1:]}: {len(files)} files, {megabytes:.2f} MB, {wall:.2f} s wall ({wall / megabytes:.1f} s/MB; median {sorted(per_file[f] for f in files)[len(files) // 2] * 1000:.0f} ms a file)")
    return "Reading (wall time of `inflections`, else `medial`, process start included): " + "; ".join(rows)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", type=Path)
    parser.add_argument("--bin", default=os.environ.get("CURVEKIT_BIN", "target/release/curvekit"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--report", type=Path, default=Path("corpus-report.json"))
    parser.add_argument("--only", help="a glob of manifest file names to run")
    args = parser.parse_args()
    manifest = json.loads((args.corpus / "manifest.json").read_text())
    entries = [e for e in manifest["files"] if not args.only or fnmatch.fnmatch(e["file"], args.only)]
    start = time.monotonic()
    outcomes = judge_corpus(str(Path(args.bin).resolve()), args.corpus.resolve(), entries, args.jobs)
    text = summary(outcomes, args.corpus, entries)
    args.report.write_text(json.dumps({"binary": str(args.bin), "corpus": str(args.corpus), "files": len(entries),
                                       "seconds": round(time.monotonic() - start, 1), "outcomes": outcomes}, indent=1) + "\n")
    print(text)
    print(f"\n{len(entries)} files, {len(outcomes)} outcomes in {time.monotonic() - start:.0f} s; report: {args.report}")


if __name__ == "__main__":
    main()
