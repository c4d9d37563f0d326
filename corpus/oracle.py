"""The independent oracle: runs one curvekit command on one drawing and judges its answer.

Nothing here calls curvekit's code: the drawing is read by `drawing` (svgelements, ezdxf), the
region is shapely's polygon of its densely flattened outlines, offsets are compared with GEOS's
`buffer`, distances and radii with distances to the flattened boundary, antipodal pairs and
inflections with the exact pieces' derivatives. Each (file, command) ends in one outcome:

    answered          exit 0 and every check holds (certified or not)
    refused           exit 2 on an input the oracle also finds invalid, naming the true cause
    refused-valid     exit 2 on an input the contract says must be answered
    refused-wrong-cause  exit 2 on an invalid input, naming some other cause
    wrong-certified   exit 0, certified, and a check fails (the worst)
    wrong-uncertified exit 0, not certified, and a check fails
    crash             any other exit status, a panic, or output that is not the promised JSON
    timeout           no answer within the time limit
"""

from __future__ import annotations

import json
import re
import subprocess
import time
from dataclasses import dataclass, field

import numpy as np
import shapely

from curve_checks import check_antipodal, check_inflections
from drawing import Drawing
from region_checks import VBIT_ANGLE, check_medial, check_offsets, check_vcarve, offset_distances, vcarve_depth

TIMEOUT = 60.0

CAUSE_WORDS = {
    "open": ("open", "gap", "not closed", "does not close", "closed curve", "no closed outline"),
    "cross": ("cross", "intersect", "meet", "touch", "overlap", "turns back"),
    "empty": ("no usable", "empty", "no geometry", "nothing", "no profile", "no curve"),
    "degenerate": ("area", "degenerate", "zero", "back", "cusp", "cross"),
    "branch": ("branch", "meet", "more than"),
    "fit": ("fit",),
}


@dataclass
class Outcome:
    file: str
    command: str
    args: list[str]
    status: str
    certified: bool | None = None
    message: str = ""
    problems: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # contract details short of a wrong answer
    wall: float = 0.0
    figures: dict = field(default_factory=dict)


@dataclass
class Answer:
    code: int | None  # None: timed out
    document: dict | None
    stderr: str
    wall: float


def run_tool(binary: str, args: list[str], timeout: float = TIMEOUT) -> Answer:
    start = time.monotonic()
    try:
        done = subprocess.run([binary, *args], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return Answer(None, None, "", time.monotonic() - start)
    wall = time.monotonic() - start
    document = None
    if done.returncode == 0:
        try:
            document = json.loads(done.stdout)
        except json.JSONDecodeError:
            document = None
    return Answer(done.returncode, document, done.stderr.strip(), wall)


def message_pattern(message: str) -> str:
    """A refusal's message without its file name and numbers, to group refusals by kind."""
    text = re.sub(r"^curvekit: [^:]*: ", "", message.splitlines()[0] if message else "")
    text = re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "N", text)
    return text[:110]


# ----------------------------------------------------------------------------------------------
# One file, every command that applies


def judge_file(binary: str, path: str, expect: dict | None = None) -> list[Outcome]:
    """Every command that applies to the drawing, each judged; `expect` is the manifest's note
    for a DXF part (what the oracle's own reading must find, and what curvekit must report)."""
    from drawing import read

    expect = expect or {}
    try:
        drawing = read(path)
    except Exception as error:  # the oracle could not read it: said so, never blamed on curvekit
        return [Outcome(path, "read", [], "oracle-error", message=f"{type(error).__name__}: {error}")]
    outcomes = []
    if expect:
        mismatch = expectation_mismatch(drawing, expect)
        if mismatch:
            return [Outcome(path, "read", [], "oracle-error", message=mismatch)]
    part_of_pick: dict[int, int] = {}
    for command in ("medial", "offset", "vcarve", "antipodal", "inflections"):
        try:
            if command in ("medial", "offset", "vcarve"):
                outcomes += judge_region(binary, drawing, command, expect, part_of_pick)
            elif single_curve_applies(drawing):
                outcomes.append(judge_curve(binary, drawing, command, expect))
        except Exception as error:  # an oracle bug must not hide the other commands' outcomes
            outcomes.append(Outcome(path, command, [], "oracle-error", message=f"{type(error).__name__}: {error}"))
    return outcomes


def expectation_mismatch(drawing: Drawing, expect: dict) -> str:
    if not expect.get("valid", True):
        return "" if not drawing.valid or expect.get("ambiguous") else "the oracle reads as valid a part noted invalid"
    holes = sorted(len(h) for _, h in drawing.parts)
    if not drawing.valid or len(drawing.parts) != expect["parts"] or holes != sorted(expect["holes"]):
        return f"the oracle reads {len(drawing.parts)} parts with holes {holes} ({drawing.invalid[:1]}), the note says {expect['parts']} with {expect['holes']}"
    return ""


def single_curve_applies(drawing: Drawing) -> bool:
    """Antipodal pairs and inflections need profile 0 to be a simple closed curve: taken only where
    every chain is closed and none crosses itself, so that profile 0 is one of the oracle's rings."""
    closed = not any(gap > 1e-4 * drawing.size for _, gap in drawing.open_chains)
    return bool(drawing.rings) and closed and not drawing.self_crossing


def refusal_cause_named(message: str, causes: list[str]) -> bool:
    text = message.lower()
    return any(word in text for cause in causes for word in CAUSE_WORDS.get(cause, (cause,)))


def base_outcome(drawing: Drawing, command: str, args: list[str], answer: Answer) -> Outcome:
    outcome = Outcome(str(drawing.path), command, args, "", wall=answer.wall)
    if answer.code is None:
        outcome.status = "timeout"
    elif answer.code == 0 and answer.document is None:
        outcome.status, outcome.message = "crash", "exit 0 without a JSON document"
    elif answer.code not in (0, 2) or "panicked" in answer.stderr:
        outcome.status, outcome.message = "crash", f"exit {answer.code}: {answer.stderr[-400:]}"
    elif answer.code == 2:
        outcome.status, outcome.message = "refused", answer.stderr
        if len(answer.stderr.splitlines()) != 1:
            outcome.notes.append("the refusal is not one line on stderr")
    else:
        outcome.certified = bool(answer.document.get("certified"))
    return outcome


def judge_refusal(drawing: Drawing, outcome: Outcome, expect: dict) -> None:
    """A refusal is right when the input is invalid and its message names the oracle's cause (or
    the cause the manifest notes for a DXF part)."""
    causes = [entry.split(":")[0] for entry in drawing.invalid] + [expect.get("cause", "")] * bool(expect.get("cause"))
    if drawing.valid:
        near_open = [a for a in drawing.ambiguous if "near-closed" in a]
        if near_open and refusal_cause_named(outcome.message, ["open"]):
            return
        outcome.status = "refused-valid"
    elif not refusal_cause_named(outcome.message, causes):
        outcome.status = "refused-wrong-cause"
        outcome.problems.append(f"the oracle finds: {drawing.invalid[0]}")


def contract_notes(drawing: Drawing, document: dict, expect: dict, outcome: Outcome) -> None:
    """What a result read from a drawing must carry beside the geometry."""
    if "skipped" not in document:
        outcome.notes.append("no 'skipped' list in a result read from a drawing")
    else:
        listed = {item.get("type"): item.get("count") for item in document["skipped"]}
        for kind, count in (expect.get("skipped") or {}).items():
            if listed.get(kind) != count:
                outcome.notes.append(f"'skipped' lists {listed.get(kind)} {kind}, the drawing has {count}")
    accepted = {"mm": ("mm",), "in": ("in", "inch", "inches")}.get(expect.get("units"), (expect.get("units"),))
    if expect.get("units") and document.get("units") not in accepted:
        outcome.notes.append(f"units {document.get('units')!r}, the drawing says {expect['units']!r}")
    if (expect.get("uncertified") or drawing.outline_skipped) and outcome.certified:
        outcome.problems.append(f"certified although an outline was skipped: {(drawing.outline_skipped or ['?'])[0]}")


def finish(outcome: Outcome, problems: list[str], figures: dict) -> Outcome:
    outcome.problems += problems
    outcome.figures.update(figures)
    if outcome.problems:
        outcome.status = "wrong-certified" if outcome.certified else "wrong-uncertified"
    else:
        outcome.status = "answered"
    return outcome


def judge_region(binary, drawing: Drawing, command: str, expect: dict, part_of_pick: dict[int, int]) -> list[Outcome]:
    """The whole drawing as one input (multi-part as the contract says); where curvekit asks for
    --pick, each part on its own as well, so that its geometry is still judged."""
    everything = list(range(len(drawing.parts)))
    extra = []
    if command == "offset":
        distances = offset_distances(drawing, everything) if drawing.valid else [float(f"{0.05 * drawing.size:.6g}") or 1.0]
        extra = ["--distances", ",".join(f"{d:g}" for d in distances)]
    if command == "vcarve":
        extra = vcarve_args(drawing, everything)
    args = [command, str(drawing.path), "--json", *extra]
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, command, args, answer)
    outcomes = [outcome]
    if outcome.status == "refused":
        judge_refusal(drawing, outcome, expect)
        if outcome.status == "refused-valid" and "--pick" in outcome.message and len(drawing.parts) > 1:
            for pick in range(len(drawing.parts)):
                outcomes.append(judge_pick(binary, drawing, command, expect, pick, part_of_pick))
    elif outcome.status == "" and not drawing.valid:
        outcome.status = "answered-invalid"
        outcome.problems.append(f"answered although {drawing.invalid[0] if drawing.invalid else 'the input holds no region'}")
    elif outcome.status == "":
        contract_notes(drawing, answer.document, expect, outcome)
        finish(outcome, *CHECKS[command](drawing, answer.document, everything, drawing.size))
    return outcomes


def vcarve_args(drawing: Drawing, parts: list[int]) -> list[str]:
    """The bit's angle, and a depth limit where the oracle reads a region (else none)."""
    depth = ["--max-depth", f"{vcarve_depth(drawing, parts):g}"] if drawing.valid else []
    return ["--angle", f"{VBIT_ANGLE:g}", *depth]


def judge_pick(binary, drawing: Drawing, command: str, expect: dict, pick: int, part_of_pick: dict[int, int]) -> Outcome:
    """One part of a multi-part drawing through --pick; which part curvekit took is read off its
    medial axis (the part holding most of its vertices), else off the offset loops."""
    args = [command, str(drawing.path), "--json", "--pick", str(pick)]
    part = part_of_pick.get(pick, pick)
    if command == "offset":
        distances = offset_distances(drawing, [part])
        args += ["--distances", ",".join(f"{d:g}" for d in distances)]
    if command == "vcarve":
        args += vcarve_args(drawing, [part])
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, f"{command} --pick", args, answer)
    outcome.figures["pick"] = pick
    if outcome.status == "refused":
        judge_refusal(drawing, outcome, expect)
        return outcome
    if outcome.status:
        return outcome
    document = answer.document
    points = [n["xy"] for n in document.get("nodes", [])] + [e["xy"][0] for e in document.get("edges", [])]
    points += [s.get("from") or s.get("center") for o in document.get("offsets", []) for loop in o.get("loops", []) for s in loop["segments"][:1]]
    points += [p["xyz"][0][:2] for p in document.get("paths", [])]
    if points and (command == "medial" or pick not in part_of_pick):
        votes = [int(np.argmin([p.distance(shapely.Point(xy)) for p in drawing.part_polygons])) for xy in points[:200] if xy is not None]
        part = max(set(votes), key=votes.count)
        part_of_pick[pick] = part
    outcome.figures["part"] = part
    polygon = drawing.part_polygons[part]
    size = float(max(np.ptp(np.asarray(polygon.bounds).reshape(2, 2), axis=0)))
    check = CHECKS[command]
    if command in ("offset", "vcarve") and part != part_of_pick.get(pick, part):
        outcome.notes.append(f"the {command} options were chosen for another part")
    contract_notes(drawing, document, expect, outcome)
    return finish(outcome, *check(drawing, document, [part], size))


CHECKS = {"medial": check_medial, "offset": check_offsets, "vcarve": check_vcarve}


def judge_curve(binary, drawing: Drawing, command: str, expect: dict) -> Outcome:
    """Antipodal pairs or inflections of profile 0 (--pick 0 where the drawing has several)."""
    several = len(drawing.rings) > 1 or drawing.outline_skipped  # curvekit may count a skipped outline
    args = [command, str(drawing.path), "--json"] + (["--pick", "0"] if several else [])
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, command, args, answer)
    if outcome.status == "refused":
        outcome.status = "refused-valid"
        return outcome
    if outcome.status:
        return outcome
    contract_notes(drawing, answer.document, expect, outcome)
    check = check_antipodal if command == "antipodal" else check_inflections
    return finish(outcome, *check(drawing, answer.document))
