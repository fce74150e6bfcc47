"""The write-up's page (tools/writeup): one self-contained HTML file, every
image inside it as a data URI, a slider per image comparison, and print
styles so that Chromium's PDF shows the same content on paper (each task
from a new page, the comparisons side by side)."""
import base64
import html
import re
from pathlib import Path

import markdown

STYLE = """
:root { --ink: #1d232b; --muted: #5b6470; --line: #d9dee4; --good: #1d7a3a; --bad: #b3261e; --todo: #8a5a00; }
* { box-sizing: border-box; }
body { font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; color: var(--ink);
       max-width: 1100px; margin: 0 auto; padding: 24px; }
h1 { margin: 0 0 4px; } h2 { border-bottom: 2px solid var(--line); padding-bottom: 4px; margin-top: 40px; }
h3 { margin: 24px 0 8px; color: #33404d; }
code, pre { font: 12.5px/1.4 ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; }
pre { background: #f5f7f9; border: 1px solid var(--line); padding: 8px; overflow-x: auto; white-space: pre-wrap; }
.meta { color: var(--muted); }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid var(--line); padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f0f3f6; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
.owner-student { color: var(--good); font-weight: 600; } .owner-reference { color: var(--muted); }
.figures { display: flex; flex-wrap: wrap; gap: 20px; }
figure { margin: 0; }
.figure { flex: 1 1 420px; max-width: 100%; }
.figure img { max-width: 100%; height: auto; border: 1px solid var(--line); display: block; }
figcaption { font-size: 13.5px; color: #33404d; margin-top: 6px; }
figcaption p { margin: 2px 0; }
.numbers { color: var(--muted); }
.notice { border-left: 5px solid; padding: 10px 14px; margin: 12px 0; background: #fbf7ee; }
.notice.undone { border-color: var(--todo); }
.notice.missing { border-color: var(--bad); background: #fcf1f0; }
.notice.empty { border-color: var(--line); background: #f6f8fa; }
.comparisons { display: flex; flex-wrap: wrap; gap: 24px; }
.compare-row { display: flex; gap: 10px; align-items: flex-start; }
.compare-frame { position: relative; line-height: 0; border: 1px solid var(--line); }
.compare-frame img, .compare-z { image-rendering: pixelated; display: block; }
.compare-frame img.yours { position: absolute; left: 0; top: 0; clip-path: inset(0 50% 0 0); }
.compare-label { position: absolute; top: 4px; font: 11px/1.4 system-ui, sans-serif; color: #fff;
                 background: rgba(0, 0, 0, 0.55); padding: 0 4px; }
.compare-label.left { left: 4px; } .compare-label.right { right: 4px; }
.compare-slider { width: 100%; margin: 6px 0 0; }
.compare-z { border: 1px solid var(--line); }
.z-legend { max-width: 460px; margin: 6px 0 12px; }
table.overview { width: 100%; }
.z-bar { height: 14px; border: 1px solid var(--line); print-color-adjust: exact; -webkit-print-color-adjust: exact;
         background: linear-gradient(to right, #0000ff 0%, #0000ff 12%, #000066 12%, #00001a 31%, #000 50%,
                                     #1a0000 69%, #660000 88%, #ff0000 88%, #ff0000 100%); }
.z-ticks { position: relative; height: 16px; font-size: 12px; color: var(--muted); }
.z-ticks span { position: absolute; transform: translateX(-50%); }
.pass { color: var(--good); font-weight: 600; } .fail { color: var(--bad); font-weight: 600; }
.answers blockquote { margin: 12px 0 6px; padding: 6px 12px; border-left: 4px solid #5a7fa8; background: #eef3f8;
                      color: #23394f; }
.answers blockquote p { margin: 2px 0; }
@media print {
  body { max-width: none; padding: 0; font-size: 11pt; }
  section.task + section.task, section.convergence { break-before: page; }  /* task 1 starts on page 1 */
  figure, .notice, tr, .z-legend { break-inside: avoid; }
  table.overview { font-size: 9pt; }  /* a row per task, and task 1's start still on page 1 */
  table.overview th, table.overview td { padding: 1px 4px; }
  .compare-slider, .compare-label { display: none; }
  .compare-frame { position: static; display: flex; gap: 8px; border: none; }
  .compare-frame img { border: 1px solid var(--line); }
  .compare-frame img.yours { position: static; clip-path: none !important; order: -1; }
  a { color: inherit; text-decoration: none; }
}
"""

# Each comparison's slider uncovers your render (left) over the reference (right).
SCRIPT = """
for (const slider of document.querySelectorAll('.compare-slider')) {
  const yours = slider.closest('.compare').querySelector('img.yours');
  const show = () => { yours.style.clipPath = 'inset(0 ' + (100 - slider.value) + '% 0 0)'; };
  slider.addEventListener('input', show);
  show();
}
"""

e = html.escape
TOOL = "tools/writeup"
NO_IMAGE_TESTS = "the suite has no image tests"  # a task's note when there is nothing to compare: not missing


def title_of(folder: str) -> str:
    """The handout's title: "# Task 3 — Bounding volume hierarchy" gives "Bounding volume hierarchy"."""
    handout = Path(__file__).resolve().parents[2] / "tasks" / folder / "README.md"
    if handout.exists():
        first = handout.read_text(encoding="utf-8").split("\n", 1)[0]
        m = re.match(r"#\s*Task\s+\d+\s*[—:-]\s*(.+)", first)
        if m:
            return m.group(1).strip()
    words = folder.split("-", 1)[1].replace("-", " ")
    return words[0].upper() + words[1:]


def student_text(path: Path):
    """writeup/NN-name.md as HTML: the course's prompts (lines starting with >) and the student's answers."""
    if not path.exists():
        return {"html": "", "written": False, "missing": str(path.name)}
    text = path.read_text(encoding="utf-8", errors="replace")
    answer_lines = [l for l in re.sub(r"<!--.*?-->", "", text, flags=re.S).splitlines()
                    if l.strip() and not l.lstrip().startswith((">", "#"))]
    body = markdown.markdown(text, extensions=["tables", "fenced_code", "sane_lists"])
    return {"html": embed_images(body, path.parent), "written": bool(answer_lines), "missing": None}


IMAGE_KINDS = {".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg", ".gif": "image/gif",
               ".svg": "image/svg+xml", ".webp": "image/webp"}


def data_uri(path: Path) -> str:
    """The picture inside the page; ValueError for a file a page cannot show or a PNG cut short."""
    kind = IMAGE_KINDS.get(path.suffix.lower())
    if kind is None:
        raise ValueError(f"{path.name}: not an image a page can show (.png, .jpg, .gif, .svg, .webp)")
    data = path.read_bytes()
    if kind == "image/png" and not data.endswith(b"IEND\xaeB`\x82"):  # cut short: a program died while writing it
        raise ValueError(f"{path.name}: an incomplete PNG")
    return f"data:{kind};base64," + base64.b64encode(data).decode()


def embed_images(body: str, folder: Path) -> str:
    """The student's own pictures (![what](file.png), next to the .md) go inside the page; a missing one is said."""
    def replace(match):
        tag = match.group(0)
        src = re.search(r'src="([^"]*)"', tag)
        alt = re.search(r'alt="([^"]*)"', tag)
        name = html.unescape(src.group(1)) if src else ""
        alt_text = (alt.group(1) if alt and alt.group(1) else e(Path(name).name or "image"))
        if name.startswith("data:"):
            return tag
        file = (folder / name).resolve()
        try:
            if not file.is_file():
                raise ValueError("not found")
            uri = data_uri(file)
        except ValueError as why:
            return f'<span class="notice missing">image {e(name)}: {e(str(why))} (next to the .md file)</span>'
        return f'<img src="{uri}" alt="{alt_text}" style="max-width: 100%">'
    return re.sub(r"<img\b[^>]*>", replace, body)


def rate(value: float) -> str:
    for unit, scale in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if value >= scale:
            return f"{value / scale:.2f}{unit}"
    return f"{value:.0f}"


def figure_html(f) -> str:
    command = f'<p><code>{e(f["command"])}</code></p>'
    if "error" in f:
        return (f'<div class="figure"><div class="notice missing"><strong>Could not be made:</strong> '
                f'{e(f["error"])}{command}<p>{e(f["caption"])}</p></div></div>')
    width, height = f["size"]
    numbers = ""
    if "stats" in f:
        s = f["stats"]
        nan = s["non_finite_samples"]
        numbers = (f'<p class="numbers">{s["seconds"]:.2f} s on {s["threads"]} threads, '
                   f'{rate(s["samples_per_second"])} samples/s, {rate(s["rays_per_second"])} rays/s, '
                   f'<span class="{"fail" if nan else ""}">{nan} NaN or Inf samples</span>; '
                   f'{s["width"]}x{s["height"]}, {s["spp"]} spp, {e(s["integrator"])} integrator, '
                   f'{e(s["sampler"])} samples, {e(s["traversal"])} traversal</p>')
    else:
        numbers = f'<p class="numbers">{f["seconds"]:.2f} s</p>'
    printed = f'<pre>{e(f["printed"])}</pre>' if f.get("printed") else ""
    return (f'<figure class="figure"><img src="{f["image"]}" width="{width}" height="{height}" '
            f'alt="{e(f["caption"])}"><figcaption><p>{e(f["caption"])}</p>{command}{numbers}{printed}'
            f'</figcaption></figure>')


def comparison_html(c, folder: str) -> str:
    width, height = c["size"]
    scale = max(1, min(8, 300 // max(1, width)))  # small test images shown larger, pixel for pixel
    w, h = width * scale, height * scale
    v = c["verdict"]
    if v is None:
        verdict = '<span class="meta">no verdict recorded</span>'
    elif v["pass"]:
        verdict = f'<span class="pass">passes</span> (worst |z| {v["worst_z"]:.2f}, limit {v["limit"]:.2f})'
    else:
        extra = f', {v["non_finite"]} NaN or Inf samples' if v["non_finite"] else ""
        verdict = f'<span class="fail">fails</span> (worst |z| {v["worst_z"]:.2f}, limit {v["limit"]:.2f}{extra})'
    name = e(c["name"])
    z = (f'<img class="compare-z" src="{c["z"]}" width="{w}" height="{h}" alt="{name}: per-block difference in '
         f'standard deviations (red: yours brighter, blue: darker)">' if c["z"] else "")
    return (f'<figure class="compare"><div class="compare-row"><div class="compare-frame">'
            f'<img class="reference" src="{c["reference"]}" width="{w}" height="{h}" alt="{name}: the reference image">'
            f'<img class="yours" src="{c["yours"]}" width="{w}" height="{h}" alt="{name}: your render">'
            f'<span class="compare-label left">yours</span><span class="compare-label right">reference</span>'
            f'</div>{z}</div>'
            f'<input class="compare-slider" type="range" min="0" max="100" value="50" '
            f'aria-label="{name}: slide to compare your render with the reference">'
            f'<figcaption><p><strong>{name}</strong> (tests/{e(folder)}/images/{name}.exr): '
            f'{verdict}</p></figcaption></figure>')


# The z-maps' colours (tests/support/image_test.cpp, zScoreMap): within the
# test's limit L the colour grows as (|z| / L)^2 up to 40 %, past it full.
Z_LEGEND = ('<div class="z-legend"><div class="z-bar"></div><div class="z-ticks"><span style="left: 12%">'
            '&minus;L</span><span style="left: 50%">0</span><span style="left: 88%">+L</span></div>'
            '<p class="meta">Left: yours darker; right: brighter. Black to dim: within noise, as a passing render '
            'looks. Full blue or red: the block differs by more than the test allows (L, the test\'s limit, is '
            'given under each picture).</p></div>')


def section_html(s) -> str:
    n, folder = s["number"], s["folder"]
    owner = s["owner"]
    who = ("yours" if owner == "student" else "the reference")
    parts = [f'<section class="task" id="task-{n}"><h2>Task {n}: {e(title_of(folder))}</h2>',
             f'<p class="meta">Code: <span class="owner-{e(owner)}">{who}</span>, <code>{e(s["file"])}</code></p>']
    if s["todos"]:
        left = ", ".join(f'{e(tag)} (line {line})' for line, tag in s["todos"])
        parts.append(f'<div class="notice undone"><strong>Not implemented yet.</strong> '
                     f'PATHLAB_TODO calls left in <code>{e(s["file"])}</code>: {left}. Its pictures appear here '
                     f'once they are gone.</div>')
    if s["figures"]:
        parts.append('<div class="figures">' + "".join(figure_html(f) for f in s["figures"]) + "</div>")
    if not s["todos"]:
        parts.append("<h3>Your renders against the reference images</h3>")
        if s["comparisons"]:
            parts.append(f'<p class="meta">The test suite\'s image tests (tests/{e(folder)}), with their verdicts: '
                         f'your render on the left of each slider, the stored reference on the right; beside them, '
                         f'each 4x4 block\'s difference in standard deviations, z. Run in '
                         f'{e(s["comparison_note"])}.</p>' + Z_LEGEND)
            parts.append('<div class="comparisons">' + "".join(comparison_html(c, folder) for c in s["comparisons"])
                         + "</div>")
        elif s["comparison_note"] == NO_IMAGE_TESTS:
            parts.append(f'<p class="meta">This task\'s suite (tests/{e(folder)}) has no image tests: its tests '
                         f'judge values, not renders.</p>')
        else:
            parts.append(f'<div class="notice missing"><strong>No comparison:</strong> '
                         f'{e(s["comparison_note"] or "not run")}</div>')
    parts.append("<h3>Your answers</h3>")
    text = s["text"]
    if text["missing"]:
        parts.append(f'<div class="notice empty">No <code>writeup/{e(text["missing"])}</code>: write your answers '
                     f'there.</div>')
    else:
        parts.append(f'<div class="answers">{text["html"]}</div>')
        if not text["written"]:
            parts.append(f'<div class="notice empty">Nothing written yet under the prompts in '
                         f'<code>writeup/{e(folder)}.md</code>.</div>')
    parts.append("</section>")
    return "\n".join(parts)


def speed_table(sections) -> str:
    rows = []
    for s in sections:
        for f in s["figures"]:
            if "stats" not in f:
                continue
            st = f["stats"]
            rows.append(f'<tr><td>{s["number"]}</td><td><code>{e(f["command"])}</code></td>'
                        f'<td>{st["width"]}x{st["height"]}, {st["spp"]} spp, -m {st["max_depth"]}</td>'
                        f'<td class="number">{st["seconds"]:.2f}</td><td class="number">{rate(st["samples_per_second"])}</td>'
                        f'<td class="number">{rate(st["rays_per_second"])}</td>'
                        f'<td class="number">{st["non_finite_samples"]}</td></tr>')
    if not rows:
        return '<div class="notice empty">No render ran (the tasks that render are not done yet).</div>'
    return ('<table><tr><th>task</th><th>command</th><th>settings</th><th>seconds</th><th>samples/s</th>'
            '<th>rays/s</th><th>NaN or Inf</th></tr>' + "".join(rows) + "</table>")


def convergence_html(c, owners) -> str:
    if c is None:
        return '<div class="notice empty">Not made (--no-convergence).</div>'
    if "error" in c:
        return f'<div class="notice missing"><strong>No convergence figure:</strong> {e(c["error"])}</div>'
    width, height = c["size"]

    def whose(row):
        if row["default"] and not row["relies_on"]:
            return "the build's own path tracer (tasks 1-5, as linked above)"
        return "the framework's tracer with " + ", ".join(
            f'task {t} {"yours" if owners.get(t) == "student" else "reference"}' for t in row["relies_on"])
    rows = "".join(f'<tr><td>{e(r["name"])}{" (default)" if r["default"] else ""}</td>'
                   f'<td class="number">{r["efficiency"]:.4g}</td><td class="number">{r["slope"]:.2f}</td>'
                   f'<td>{e(whose(r))}</td></tr>' for r in c["table"])
    summary = f'<p>{e(c["summary"])}.</p>' if c["summary"] else ""
    return (f'<figure class="figure"><img src="{c["image"]}" width="{width}" height="{height}" alt="Relative mean '
            f'squared error against samples per pixel and against seconds, one line per sampling strategy">'
            f'<figcaption><p>Error against samples per pixel and against time, per sampling strategy your build '
            f'supports, measured against your build\'s own render at {c["reference_spp"]} samples per pixel (so '
            f'the last points are a little pessimistic); {c["seconds"]:.0f} s.</p>'
            f'<p><code>{e(c["command"])}</code></p></figcaption></figure>'
            f'<table><tr><th>strategy</th><th>efficiency: 1 / (relMSE × seconds)</th><th>slope of log relMSE '
            f'against log spp</th><th>code it runs</th></tr>{rows}</table>{summary}')


def overview_table(sections) -> str:
    """Page 1: each task's state at a glance, linked to its section."""
    rows = []
    for s in sections:
        n, owner = s["number"], s["owner"]
        code = f'<span class="owner-{e(owner)}">{"yours" if owner == "student" else "reference"}</span>'
        if s["todos"]:
            code += f', <span class="fail">{len(s["todos"])} TODO{"s" if len(s["todos"]) > 1 else ""} left</span>'
        verdicts = [c["verdict"] for c in s["comparisons"] if c.get("verdict")]
        if s["todos"]:
            images = "not run yet"
        elif not verdicts:
            images = e(s["comparison_note"] or "none") if not s["comparisons"] else f'{len(s["comparisons"])} shown'
        else:
            passed = sum(1 for v in verdicts if v["pass"])
            worst = max(verdicts, key=lambda v: v["worst_z"] / v["limit"])
            images = (f'<span class="{"pass" if passed == len(verdicts) else "fail"}">{passed} of {len(verdicts)} '
                      f'pass</span>; worst block |z| {worst["worst_z"]:.2f} (limit {worst["limit"]:.2f})')
        text = s["text"]
        answers = ("no file" if text["missing"] else "written" if text["written"] else
                   '<span class="fail">not yet</span>')
        rows.append(f'<tr><td><a href="#task-{n}">Task {n}: {e(title_of(s["folder"]))}</a></td><td>{code}</td>'
                    f'<td>{images}</td><td>{answers}</td></tr>')
    return ('<table class="overview"><tr><th>task</th><th>code</th><th>image tests</th><th>your answers</th></tr>'
            + "".join(rows) + '<tr><td colspan="4"><a href="#convergence">Convergence and speed</a></td></tr>'
            '</table>')


def page(sections, converge, owners, meta) -> str:
    code = ", ".join(f'{n}: <span class="owner-{e(who)}">{"yours" if who == "student" else e(who)}</span>'
                     for n, who in sorted(owners.items()))
    undone = [s["number"] for s in sections if s["todos"]]
    status = (f"{len(sections) - len(undone)} of {len(sections)} tasks done" +
              (f" (not yet: {', '.join(map(str, undone))})" if undone else ""))
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>PathLab write-up</title>
<style>{STYLE}</style>
</head>
<body>
<header>
<h1>PathLab write-up{" (the untouched stubs)" if meta["stubs"] else ""}</h1>
<p class="meta">Made {e(meta["date"])} by <code>{e(TOOL)}</code> from <code>{e(meta["build"])}</code>
(<code>{e(meta["program"])}</code>) in {meta["seconds"]:.0f} s. {e(status)}.</p>
<p class="meta">Code linked, per task: {code}.</p>
{overview_table(sections)}
</header>
<main>
{"".join(section_html(s) for s in sections)}
<section class="convergence" id="convergence">
<h2>Convergence and speed</h2>
{convergence_html(converge, owners)}
<h3>Speed of the renders above</h3>
{speed_table(sections)}
</section>
</main>
<script>{SCRIPT}</script>
</body>
</html>
"""
