#!/usr/bin/env python3
"""Copy the CI sample of the corpus into fixtures/corpus: every DXF part, a fixed draw of icons
and glyphs per source, and the files named in NOTABLE (inputs that showed a class of failure).

    python corpus/sample.py CORPUS_DIR [--out fixtures/corpus]

Writes the sample's manifest.json (each entry with the oracle's verdict `valid`: whether the
contract requires an answer) and LICENSES.md with every source's licence text.
"""

from __future__ import annotations

import argparse
import json
import random
import shutil
import sys
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from drawing import read  # noqa: E402
from gather import FONTS, ICON_SETS, SEED  # noqa: E402

PER_ICON_SET = 6
PER_FONT = 6
NOTABLE = [
    "icons/phosphor-fill/heart-fill.svg",
    "icons/ionicons-filled/caret-back.svg",
    "icons/ionicons-filled/rose.svg",
    "icons/octicons/person-cursor-24.svg",
    "icons/heroicons-solid/document-plus.svg",
    "icons/heroicons-solid/server-stack.svg",
    "icons/fontawesome-solid/bacteria.svg",
    "icons/ionicons-filled/add.svg",
    "glyphs/noto-sans/0040-at.svg",
    "glyphs/noto-serif/0040-at.svg",
]


def choose(entries: list[dict]) -> list[dict]:
    by_source = defaultdict(list)
    for entry in entries:
        by_source[entry["source"]].append(entry)
    chosen = []
    for source, members in sorted(by_source.items()):
        members = sorted(members, key=lambda e: e["file"])
        if source == "dxf-parts":
            chosen += members
            continue
        count = PER_ICON_SET if any(s.name == source for s in ICON_SETS) else PER_FONT
        chosen += random.Random(f"{SEED}:sample:{source}").sample(members, count)
    notable = [e for e in entries if e["file"] in NOTABLE and e not in chosen]
    return sorted(chosen + notable, key=lambda e: e["file"])


def licences(corpus: Path, chosen: list[dict]) -> str:
    lines = ["# Licences of the corpus sample", "",
             "The files under this folder come from these packages; each keeps its licence.", ""]
    sources = sorted({e["source"] for e in chosen})
    for source in sources:
        entry = next(e for e in chosen if e["source"] == source)
        lines += [f"## {source}", "", f"Package `{entry['package']}` {entry['version']}, licence `{entry['licence']}`.", ""]
        if source == "dxf-parts":
            lines += ["Written for this project by corpus/dxf_parts.py with ezdxf (MIT); the drawings are dedicated to the public domain (CC0-1.0).", ""]
            continue
        icon = next((s for s in ICON_SETS if s.name == source), None)
        text_file = corpus / "licenses" / (f"{source}.txt" if icon else f"{next(f.package for f in FONTS if f.name == source)}.txt")
        lines += ["```", text_file.read_text(errors="replace").strip(), "```", ""]
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", type=Path)
    parser.add_argument("--out", type=Path, default=Path(__file__).resolve().parents[1] / "fixtures" / "corpus")
    args = parser.parse_args()
    manifest = json.loads((args.corpus / "manifest.json").read_text())
    chosen = choose(manifest["files"])
    if args.out.exists():
        shutil.rmtree(args.out)
    entries = []
    for entry in chosen:
        target = args.out / entry["file"]
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(args.corpus / entry["file"], target)
        drawing = read(target)
        entries.append(dict(entry, valid=drawing.valid))
    (args.out / "manifest.json").write_text(json.dumps({"seed": SEED, "files": entries}, indent=1) + "\n")
    (args.out / "LICENSES.md").write_text(licences(args.corpus, chosen))
    total = sum(p.stat().st_size for p in args.out.rglob("*") if p.is_file())
    print(f"{len(entries)} files, {total / 1e6:.2f} MB in {args.out}")


if __name__ == "__main__":
    main()
