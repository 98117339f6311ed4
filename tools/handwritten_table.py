#!/usr/bin/python3
"""Writes the table "Written by hand" of docs/architecture.md from handwritten_cost's CSV.

Usage: tools/handwritten_table.py HANDWRITTEN.csv ARCHITECTURE.md
Replaces what lies between the markers <!-- handwritten:begin --> and <!-- handwritten:end -->.
Every number and verdict is computed here from the measurements, never typed by hand.
"""
import csv
import sys

BEGIN, END = "<!-- handwritten:begin -->", "<!-- handwritten:end -->"
# Ours is kept for its speed when the library takes at least this many times as long.
FASTER = 1.2
# Ours is kept for the library's allocations when the library makes at least this many per call
# (a stream calls these every frame: any steady allocation is churn in the streaming thread).
ALLOCS = 1
# Reasons that are not a number: why a routine stays whatever the timing says (checked in the
# code; see the routine's file).
REASONS = {
    "Painter::text": "the painter writes each of the element's 21 formats in place, component by "
                     "component through GstVideoFormatInfo (subsampling, NV12's interleaved "
                     "chroma, YUY2/UYVY's macro-pixels, alpha); cv::putText draws whole pixels of "
                     "one cv::Mat, so those formats would need code per format or a conversion "
                     "per frame. OpenCV itself is there (the plugin links libprojtrack, which "
                     "links it): that is not the reason",
    "SilhouetteModel::recentre": "not measured alone (a private step of SilhouetteModel)",
    "packed_rgb_to_color": "OpenCV's I420 chroma is each 2×2 block's top-left pixel; the tracker "
                           "reads each block's mean, as an encoder's or videoconvert's I420 "
                           "holds it, so that one picture as RGB and as I420 reads alike "
                           "(element.md, Formats: tests/gst/test_formats.py)",
}


def us(v):
    if v == "":
        return "not measured"
    x = float(v)
    return f"{x / 1000:.2f} ms" if x >= 1000 else f"{x:.1f} µs" if x >= 10 else f"{x:.2f} µs"


def allocs(v):
    return "" if v == "" else f"{float(v):.3g}"


def verdict(row):
    reason = next((why for key, why in REASONS.items() if key in row["where"]), "")
    if row["ours_us"] == "":
        return "keep: " + (reason or row["note"])
    ratio = float(row["library_us"]) / float(row["ours_us"])
    lib_allocs = float(row["library_allocs"])
    ours_allocs = float(row["ours_allocs"])
    why = []
    if ratio >= FASTER:
        why.append(f"{ratio:.1f}× faster")
    if lib_allocs >= ALLOCS and lib_allocs > ours_allocs:
        why.append(f"the library allocates {lib_allocs:.3g} per call"
                   + ("" if ratio >= FASTER else f" (though it takes {ratio:.2f}× our time)"))
    if reason:
        why.append(reason)
    if why:
        return "keep: " + "; ".join(why)
    return (f"**replace**: the library takes {ratio:.2f}× our time and allocates nothing per "
            "call")


def cell(text):
    """Text as one Markdown table cell."""
    return text.replace("|", "\\|")


def table(rows):
    out = ["| routine | where | library equivalent | input | ours: time, allocs | "
           "library: time, allocs | same output | verdict |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        ours = f"{us(r['ours_us'])}, {allocs(r['ours_allocs'])}" if r["ours_us"] else "–"
        lib = f"{us(r['library_us'])}, {allocs(r['library_allocs'])}"
        out.append("| " + " | ".join(cell(c) for c in (
            r["routine"], f"`{r['where']}`", r["library"], r["input"], ours, lib,
            r["same"] or "–", verdict(r))) + " |")
    return out


def next_steps(rows):
    replace = [r for r in rows if verdict(r).startswith("**replace**")]
    if not replace:
        return ["Every routine has a measured reason to stay on every input."]
    names = []
    for r in replace:
        same = "the same output" if r["same"].startswith("yes") else "not the same output"
        name = f"`{r['where']}` ({r['input']}: {same})"
        if name not in names:
            names.append(name)
    return ["Next steps, not done here (the tracker is changing in parallel): the candidates "
            "for replacement, where the library is at least as fast and allocates nothing per "
            "call on the input named. Replace one only where the tracker's outputs stay "
            "identical on the test and benchmark sets: " + "; ".join(names) + "."]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    with open(sys.argv[2]) as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc:
        sys.exit(f"{sys.argv[2]}: no markers {BEGIN} {END}")
    body = table(rows) + [""] + next_steps(rows)
    head, rest = doc.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(sys.argv[2], "w") as f:
        f.write(head + BEGIN + "\n" + "\n".join(body) + "\n" + END + tail)


if __name__ == "__main__":
    main()
