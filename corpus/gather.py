#!/usr/bin/env python3
"""Gather curvekit's real-world corpus (issue 38): filled icons from npm packages, glyph outlines
from Debian's font packages, and DXF parts written with ezdxf.

    python corpus/gather.py [--cache DIR] [--out DIR]

Packages are downloaded once into the cache (default ~/.cache/curvekit-corpus, never the
repository) with the ordinary clients (`npm pack`, `apt-get download`); the corpus goes to --out
(default <cache>/corpus) with manifest.json: per file its source, package, version, licence and,
for DXF parts, what the drawing holds and what the right answer is. The selection is
deterministic: sorted names, a fixed seed. Needs Python 3 with fonttools and ezdxf, npm, apt-get
(after `apt-get update`) and dpkg-deb.
"""

from __future__ import annotations

import argparse
import fnmatch
import json
import random
import shutil
import subprocess
import sys
import tarfile
from dataclasses import dataclass
from pathlib import Path

SEED = 38  # the number: any fixed value keeps the selection the same


@dataclass(frozen=True)
class IconSet:
    name: str
    package: str  # npm package
    version: str
    folder: str  # inside the tarball
    pattern: str  # file name pattern of the filled icons
    exclude: tuple[str, ...]
    licence: str  # SPDX id of the icons
    licence_file: str  # inside the tarball
    count: int


ICON_SETS = [
    IconSet("fontawesome-solid", "@fortawesome/fontawesome-free", "7.3.1", "package/svgs/solid", "*.svg", (), "CC-BY-4.0", "package/LICENSE.txt", 35),
    IconSet("octicons", "@primer/octicons", "19.42.0", "package/build/svg", "*-24.svg", (), "MIT", "package/LICENSE", 35),
    IconSet("remixicon-fill", "remixicon", "4.9.1", "package/icons/*", "*-fill.svg", (), "Apache-2.0", "package/License", 35),
    IconSet("phosphor-fill", "@phosphor-icons/core", "2.1.1", "package/assets/fill", "*-fill.svg", (), "MIT", "package/LICENSE", 35),
    IconSet("heroicons-solid", "heroicons", "2.2.0", "package/24/solid", "*.svg", (), "MIT", "package/LICENSE", 35),
    IconSet("ionicons-filled", "ionicons", "8.1.0", "package/dist/svg", "*.svg", ("*-outline.svg", "*-sharp.svg"), "MIT", "package/LICENSE", 35),
]


@dataclass(frozen=True)
class Font:
    name: str
    package: str  # Debian package
    file: str  # path inside the package
    licence: str


FONTS = [
    Font("noto-sans", "fonts-noto-core", "usr/share/fonts/truetype/noto/NotoSans-Regular.ttf", "OFL-1.1"),
    Font("noto-serif", "fonts-noto-core", "usr/share/fonts/truetype/noto/NotoSerif-Regular.ttf", "OFL-1.1"),
    Font("roboto", "fonts-roboto-unhinted", "usr/share/fonts/truetype/roboto/unhinted/RobotoTTF/Roboto-Regular.ttf", "Apache-2.0"),
    Font("cantarell", "fonts-cantarell", "usr/share/fonts/opentype/cantarell/Cantarell-Regular.otf", "OFL-1.1"),
    Font("dejavu-sans", "fonts-dejavu-core", "usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "Bitstream-Vera AND LicenseRef-DejaVu-public-domain"),
]

# Letters and signs with holes (counters) first, then others with tight turns and several parts.
GLYPHS = "aAbBdDeEgGoOpPqQR0123456789&%@#$?!ijsS"


def run(command: list[str], cwd: Path | None = None) -> str:
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"gather: {' '.join(command)} failed:\n{done.stderr.strip()}")
    return done.stdout


def npm_package(icon_set: IconSet, cache: Path) -> Path:
    """The package's tarball, unpacked once into the cache."""
    folder = cache / "npm" / f"{icon_set.package.replace('/', '+')}-{icon_set.version}"
    if not (folder / "package").exists():
        folder.mkdir(parents=True, exist_ok=True)
        name = run(["npm", "pack", f"{icon_set.package}@{icon_set.version}", "--silent"], cwd=folder).strip().splitlines()[-1]
        with tarfile.open(folder / name) as archive:
            # the "data" filter (no links out, no special files) where this Python has it
            archive.extractall(folder, **({"filter": "data"} if hasattr(tarfile, "data_filter") else {}))
    return folder


def deb_package(package: str, cache: Path) -> tuple[Path, str]:
    """The package's files, unpacked once into the cache, and its version."""
    folder = cache / "deb" / package
    if not (folder / "root").exists():
        folder.mkdir(parents=True, exist_ok=True)
        run(["apt-get", "download", package], cwd=folder)
        deb = next(folder.glob("*.deb"))
        run(["dpkg-deb", "-x", str(deb), str(folder / "root")])
    deb = next(folder.glob("*.deb"))
    version = run(["dpkg-deb", "-f", str(deb), "Version"]).strip()
    return folder / "root", version


def choose(names: list[str], count: int, salt: str) -> list[str]:
    """A fixed sample of sorted names."""
    names = sorted(names)
    return sorted(random.Random(f"{SEED}:{salt}").sample(names, min(count, len(names))))


def gather_icons(cache: Path, out: Path, licences: Path) -> list[dict]:
    entries = []
    for icon_set in ICON_SETS:
        root = npm_package(icon_set, cache)
        candidates = {}
        for path in root.glob(f"{icon_set.folder}/{icon_set.pattern}"):
            if not any(fnmatch.fnmatch(path.name, pattern) for pattern in icon_set.exclude):
                candidates.setdefault(path.name, path)
        shutil.copyfile(root / icon_set.licence_file, licences / f"{icon_set.name}.txt")
        target = out / "icons" / icon_set.name
        target.mkdir(parents=True, exist_ok=True)
        for name in choose(list(candidates), icon_set.count, icon_set.name):
            shutil.copyfile(candidates[name], target / name)
            entries.append({
                "file": f"icons/{icon_set.name}/{name}", "kind": "icon", "source": icon_set.name,
                "package": f"npm:{icon_set.package}", "version": icon_set.version, "licence": icon_set.licence,
            })
    return entries


def glyph_svg(font_path: Path, char: str) -> tuple[str, str] | None:
    """One glyph's outline as an SVG path in font units, flipped to SVG's y-down by a transform."""
    from fontTools.pens.boundsPen import BoundsPen
    from fontTools.pens.svgPathPen import SVGPathPen
    from fontTools.ttLib import TTFont

    font = TTFont(font_path)
    name = font.getBestCmap().get(ord(char))
    if name is None:
        return None
    glyphs = font.getGlyphSet()
    pen, bounds = SVGPathPen(glyphs), BoundsPen(glyphs)
    glyphs[name].draw(pen)
    glyphs[name].draw(bounds)
    if bounds.bounds is None:
        return None
    x0, y0, x1, y1 = bounds.bounds
    margin = 0.05 * max(x1 - x0, y1 - y0)
    view = f"{x0 - margin:g} {-y1 - margin:g} {x1 - x0 + 2 * margin:g} {y1 - y0 + 2 * margin:g}"
    svg = (
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{view}">\n'
        f'  <!-- glyph "{name}" (U+{ord(char):04X}) of {font_path.name}, font units, y flipped -->\n'
        f'  <g transform="matrix(1 0 0 -1 0 0)"><path d="{pen.getCommands()}"/></g>\n</svg>\n'
    )
    return name, svg


def gather_glyphs(cache: Path, out: Path, licences: Path) -> list[dict]:
    entries = []
    for font in FONTS:
        root, version = deb_package(font.package, cache)
        copyright_file = root / "usr/share/doc" / font.package / "copyright"
        shutil.copyfile(copyright_file, licences / f"{font.package}.txt")
        target = out / "glyphs" / font.name
        target.mkdir(parents=True, exist_ok=True)
        for char in GLYPHS:
            made = glyph_svg(root / font.file, char)
            if made is None:
                continue
            name, svg = made
            file_name = f"{ord(char):04x}-{name}.svg"  # the code keeps 'a' and 'A' apart everywhere
            (target / file_name).write_text(svg)
            entries.append({
                "file": f"glyphs/{font.name}/{file_name}", "kind": "glyph", "source": font.name,
                "package": f"deb:{font.package}", "version": version, "licence": font.licence,
                "note": f"glyph {char!r} of {Path(font.file).name}",
            })
    return entries


def gather_dxf(out: Path) -> list[dict]:
    import ezdxf

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import dxf_parts

    target = out / "dxf"
    target.mkdir(parents=True, exist_ok=True)
    entries = []
    for make in dxf_parts.PARTS:
        document, note, expectation = make()
        path = target / f"{make.__name__}.dxf"
        document.saveas(path)
        entries.append({
            "file": f"dxf/{path.name}", "kind": "dxf", "source": "dxf-parts", "package": "pypi:ezdxf",
            "version": ezdxf.__version__, "licence": "CC0-1.0", "note": note, "expect": expectation,
        })
    return entries


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cache", type=Path, default=Path.home() / ".cache" / "curvekit-corpus")
    parser.add_argument("--out", type=Path, help="default: <cache>/corpus")
    args = parser.parse_args()
    cache = args.cache.expanduser().resolve()
    out = (args.out or cache / "corpus").expanduser().resolve()
    if out.exists():
        shutil.rmtree(out)
    licences = out / "licenses"
    licences.mkdir(parents=True)
    entries = gather_icons(cache, out, licences) + gather_glyphs(cache, out, licences) + gather_dxf(out)
    (out / "manifest.json").write_text(json.dumps({"seed": SEED, "files": entries}, indent=1) + "\n")
    counts = {}
    for entry in entries:
        counts[entry["source"]] = counts.get(entry["source"], 0) + 1
    print(f"{len(entries)} files in {out}: " + ", ".join(f"{k} {v}" for k, v in counts.items()))


if __name__ == "__main__":
    main()
