#!/usr/bin/python3
"""Writes docs/performance.md from projtrack-speed's measurements (./run bench --speed).

Usage: bench/speed/report.py DATA_DIR OUTPUT.md
Reads DATA_DIR/speed.csv, DATA_DIR/methods.csv (the table of methods) and DATA_DIR/meta.json;
draws DATA_DIR/figures/cost_by_object_size.svg.
Every number and verdict is computed here from the measurements or read from meta.json, never
written by hand; a target whose numbers are missing reads "not measured", never "met".
The page's parts: speed_data.py (reading speed.csv, the targets' numbers), speed_targets.py (the
targets' verdicts), speed_sections.py and speed_bounded.py (the sections).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, HERE)  # its parts, also when loaded from elsewhere (tests/bench)
# MISSING, ELEMENT, speed_phrase, targets and bounded_targets: tests/bench/test_speed_report.py
# reads them from this module.
from report_kit import MISSING, load_methods, plt  # noqa: E402,F401
from speed_bounded import bounded_section, ordinary_work_section  # noqa: E402
from speed_data import (ELEMENT, growth_by_method, load, megapixels, size_rows,  # noqa: E402,F401
                        speed_phrase)
from speed_sections import (allocations_section, edges_section, fast_section,  # noqa: E402
                            intro_and_targets, per_frame_section, reproduce_section,
                            size_section, statuses_section, streams_section)
from speed_targets import bounded_targets, targets  # noqa: E402,F401


def size_figure(sizes, methods, resolutions, path):
    fig, axes = plt.subplots(1, max(1, len(resolutions)), figsize=(11, 4.2), sharey=True,
                             squeeze=False)
    for ax, res in zip(axes[0], resolutions):
        for m in methods:
            pts = sizes.get((res, m), [])
            if pts:
                ax.plot([p for p, _ in pts], [u / 1000 for _, u in pts], marker="o", label=m)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"{res}: {megapixels(res)} frame")
        ax.set_xlabel("object area (px)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("ms per frame (library, one thread)")
    axes[0][-1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    data_dir, out_md = sys.argv[1], sys.argv[2]
    rows, meta = load(data_dir)
    methods = [m["method"] for m in load_methods(data_dir)]
    default = next((r["key"] for r in rows if r["section"] == "meta"
                    and r["what"] == "default method"), None)
    if default is None:
        sys.exit("bench/speed/report.py: speed.csv does not say the element's default method")
    os.makedirs(os.path.join(data_dir, "figures"), exist_ok=True)
    sizes = size_rows(rows)
    growth, resolutions, pixel_ratio = growth_by_method(sizes, methods)
    fig_path = os.path.join(data_dir, "figures", "cost_by_object_size.svg")
    size_figure(sizes, methods, resolutions, fig_path)
    rel = lambda p: os.path.relpath(p, os.path.dirname(os.path.abspath(out_md)))  # noqa: E731

    md = intro_and_targets(rows, meta, default, methods)
    md += per_frame_section(rows, meta, methods, default)
    md += statuses_section(rows, methods, default)
    md += size_section(growth, resolutions, pixel_ratio, rel(fig_path))
    md += edges_section(rows, default)
    md += allocations_section(rows)
    md += streams_section(rows)
    md.extend(bounded_section(rows, methods, default))
    md.extend(ordinary_work_section(rows))
    md += fast_section(rows, meta)
    md += reproduce_section(data_dir, rel)
    with open(out_md, "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main()
