#!/usr/bin/env python3
"""tools/writeup, checked as a reader meets it: in a real browser and on paper.

  check_writeup.py BUILD [--screenshots DIR] [--keep DIR]

Makes the write-up three times: the build's own pathlab (the reference in
the course repository) on four tasks drawn by the commit's hash, as CI's
other samples draw (PATHLAB_WRITEUP_TASKS=1,5 names them; the whole
reference page took 270 s of the test stage), the untouched stubs
(pathlab-stubs) and a mix (tests' pathlab-mixed: the reference for tasks
1-3, the stubs for the rest) on every task. For each:
1. The page is valid HTML (tidy: no error, no warning), every <img> has alt
   text and its picture inside the page (a data: URI), nothing is fetched
   from elsewhere; a task not done has its "Not implemented yet" box and no
   pictures, a done task its pictures and no such box.
2. In headless Chromium (driven over --remote-debugging-pipe, the DevTools
   protocol, no extra package): every image loaded (complete, with a natural
   size), no console error and no uncaught exception, and dragging a
   comparison's slider with the mouse moves the boundary between the two
   renders. A screenshot of the top of the page is written (--screenshots:
   the docs' pictures).
3. The PDF (Chromium's print-to-PDF): page 1 holds the title, the overview
   (a row per task) and the start of the first task; each later section
   starts a page, in order, with the convergence section last (pdftotext per
   page); and it holds at least as many images as the page has (pdfimages)."""
import argparse
import base64
import fcntl
import html.parser
import json
import os
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks
PYTHON = "/usr/bin/python3" if Path("/usr/bin/python3").exists() else sys.executable


class Images(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.links = [], []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img":
            self.images.append(a)
        for key in ("src", "href"):
            if key in a and tag != "img":
                self.links.append(a[key])


class Chromium:
    """The DevTools protocol over a pipe: JSON messages ending in NUL, ours on fd 3, its answers on fd 4."""

    def __init__(self, browser):
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()
        # Above the numbers the child is given, so that placing them on 3 and 4 cannot overwrite one.
        high_r, high_w = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD, 10), fcntl.fcntl(from_browser_w, fcntl.F_DUPFD, 10)
        os.close(to_browser_r), os.close(from_browser_w)
        self.profile = tempfile.mkdtemp(prefix="pathlab-chromium-")
        flags = ["--headless", "--remote-debugging-pipe", "--disable-gpu", "--no-first-run", "--hide-scrollbars",
                 f"--user-data-dir={self.profile}", "--window-size=1200,900"]
        if os.geteuid() == 0:
            flags.append("--no-sandbox")

        def child():
            os.dup2(high_r, 3), os.dup2(high_w, 4)
        self.process = subprocess.Popen([browser, *flags, "about:blank"], preexec_fn=child, close_fds=False,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(high_r), os.close(high_w)
        self.next_id, self.answers, self.events = 0, {}, queue.Queue()
        self.lock, self.answered = threading.Lock(), threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.call(f"{domain}.enable", session=True)

    def _read(self):
        buffer = b""
        while True:
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                return
            buffer += chunk
            while b"\0" in buffer:
                message, buffer = buffer.split(b"\0", 1)
                m = json.loads(message)
                if "id" in m:
                    with self.answered:
                        self.answers[m["id"]] = m
                        self.answered.notify_all()
                else:
                    self.events.put(m)

    def call(self, method, session=False, timeout=60, **params):
        with self.lock:
            self.next_id += 1
            i = self.next_id
        message = {"id": i, "method": method, "params": params}
        if session:
            message["sessionId"] = self.session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.time() + timeout
        with self.answered:
            while i not in self.answers:
                if not self.answered.wait(max(0.0, deadline - time.time())):
                    raise TimeoutError(f"{method}: no answer in {timeout} s")
            answer = self.answers.pop(i)
        if "error" in answer:
            raise RuntimeError(f"{method}: {answer['error']}")
        return answer.get("result", {})

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", session=True, expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError(f"{expression[:60]}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def open(self, url, timeout=60):
        """Navigates and waits for the load event; returns the console errors and exceptions seen meanwhile."""
        self.call("Page.navigate", session=True, url=url)
        deadline, loaded, problems = time.time() + timeout, False, []
        while time.time() < deadline and not loaded:
            try:
                m = self.events.get(timeout=max(0.01, deadline - time.time()))
            except queue.Empty:
                break
            loaded = m.get("method") == "Page.loadEventFired"
            problems += self._problem(m)
        if not loaded:
            raise TimeoutError(f"{url}: not loaded in {timeout} s")
        return problems

    def problems(self):
        found = []
        while not self.events.empty():
            found += self._problem(self.events.get())
        return found

    @staticmethod
    def _problem(m):
        method, p = m.get("method"), m.get("params", {})
        if method == "Runtime.exceptionThrown":
            return [f"exception: {p['exceptionDetails'].get('text')} {p['exceptionDetails'].get('exception', {}).get('description', '')}"]
        if method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            return ["console error: " + " ".join(str(a.get("value", a.get("description"))) for a in p.get("args", []))]
        if method == "Log.entryAdded" and p["entry"].get("level") == "error":
            return [f"log error: {p['entry'].get('text')} {p['entry'].get('url', '')}"]
        return []

    def mouse(self, kind, x, y, buttons=0):
        self.call("Input.dispatchMouseEvent", session=True, type=kind, x=x, y=y, button="left", buttons=buttons,
                  clickCount=1 if kind != "mouseMoved" else 0)

    def screenshot(self, path, width=1200, height=1500):
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=width, height=height, deviceScaleFactor=1,
                  mobile=False)
        self.evaluate("window.scrollTo(0, 0)")
        data = self.call("Page.captureScreenshot", session=True, format="png")["data"]
        Path(path).write_bytes(base64.b64decode(data))

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def make(build, out, *flags):
    start = time.time()
    run = subprocess.run([PYTHON, str(ROOT / "tools" / "writeup"), "--build", str(build), "--out", str(out), *flags],
                         capture_output=True, text=True, timeout=900)
    return run, time.time() - start


def check_page(name, page: Path, pdf: Path, browser: Chromium, expect_done, expect_undone, shots, failures):
    def fail(why):
        failures.append(f"{name}: {why}")

    text = page.read_text(encoding="utf-8")
    tidy = subprocess.run(["tidy", "-q", "-e", str(page)], capture_output=True, text=True)
    if tidy.returncode != 0:
        fail(f"tidy found problems (exit {tidy.returncode}):\n{tidy.stderr[:2000]}")
    parsed = Images()
    parsed.feed(text)
    for image in parsed.images:
        if not image.get("alt", "").strip():
            fail(f"an image without alt text: {str(image)[:120]}")
        if not image.get("src", "").startswith("data:image/"):
            fail(f"an image not inside the page: {image.get('src', '')[:120]}")
    for link in parsed.links:
        if not link.startswith("#"):
            fail(f"a link out of the page: {link[:120]}")
    sections = re.findall(r'<section class="task" id="task-(\d+)">(.*?)</section>', text, re.S)
    for number, body in sections:
        n = int(number)
        undone, pictures = "Not implemented yet" in body, "<img" in body.split("<h3>Your answers</h3>")[0]
        if n in expect_undone and (not undone or pictures):
            fail(f"task {n} is not done: it should have the box and no picture (box {undone}, pictures {pictures})")
        if n in expect_done and (undone or not pictures):
            fail(f"task {n} is done: it should have its pictures and no box (box {undone}, pictures {pictures})")
        if n in expect_done and "Could not be made" in body:
            fail(f"task {n}: a picture could not be made: "
                 f"{re.search(r'Could not be made:</strong>(.*?)<', body, re.S).group(1).strip()[:300]}")
    if sorted(int(n) for n, _ in sections) != sorted(expect_done | expect_undone):
        fail(f"sections for tasks {[n for n, _ in sections]}")

    problems = browser.open(page.resolve().as_uri())
    time.sleep(0.3)
    problems += browser.problems()
    for p in problems:
        fail(f"in the browser: {p}")
    # Loaded, with a size, and decodable in full (a truncated PNG still has a size).
    loaded = browser.evaluate("""Promise.all([...document.images].map(i => i.decode().then(
        () => [i.complete && i.naturalWidth > 0, i.alt], () => [false, i.alt])))""")
    broken = [alt for ok, alt in loaded if not ok]
    if broken:
        fail(f"{len(broken)} of {len(loaded)} images did not load: {broken[:5]}")
    if len(loaded) != len(parsed.images):
        fail(f"the browser shows {len(loaded)} images, the page has {len(parsed.images)}")
    sliders = browser.evaluate("document.querySelectorAll('.compare-slider').length")
    if expect_done and sliders == 0:
        fail("no comparison slider")
    if sliders:
        rect = browser.evaluate("""(() => { const s = document.querySelector('.compare-slider');
            s.scrollIntoView({block: 'center'}); const r = s.getBoundingClientRect();
            return [r.left, r.top, r.width, r.height]; })()""")
        clip = "document.querySelector('.compare img.yours').style.clipPath"
        before = browser.evaluate(clip)
        left, top, width, height = rect
        y = top + height / 2
        browser.mouse("mousePressed", left + width / 2, y, 1)
        for k in range(1, 11):
            browser.mouse("mouseMoved", left + width / 2 + k * 0.035 * width, y, 1)
        browser.mouse("mouseReleased", left + width * 0.85, y)
        value, after = browser.evaluate("+document.querySelector('.compare-slider').value"), browser.evaluate(clip)
        if not (value >= 80 and after != before and re.fullmatch(r"inset\(0(px)? (\d+(\.\d+)?)% 0(px)? 0(px)?\)", after)
                and float(re.findall(r"[\d.]+%", after)[0][:-1]) <= 20):
            fail(f"dragging the slider to 85 %: value {value}, clip {before!r} -> {after!r}")
    if shots:
        browser.screenshot(shots / f"writeup-{name}.png")

    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True)
    pages = int(re.search(r"Pages:\s+(\d+)", info.stdout).group(1)) if info.returncode == 0 else 0
    if pages < len(sections) + 1:
        fail(f"the PDF has {pages} pages; want at least {len(sections) + 1} (one per task, convergence)")
    starts, page_one = [], ""
    for p in range(1, pages + 1):
        text = subprocess.run(["pdftotext", "-f", str(p), "-l", str(p), "-layout", str(pdf), "-"],
                              capture_output=True, text=True).stdout
        page_one = page_one or text
        first = text.strip().splitlines()
        head = first[0].strip() if first else ""
        if p == 1:
            continue
        m = re.match(r"Task (\d+):", head)
        if m:
            starts.append(int(m.group(1)))
        elif head.startswith("Convergence and speed"):
            starts.append("convergence")
    want = [int(n) for n, _ in sections][1:] + ["convergence"]
    if starts != want:
        fail(f"the PDF's pages after the first start with {starts}; want each later section on a new page, in "
             f"order: {want}")
    # Page 1: the title, the overview (a row per task) and the first task's own start, not a title alone.
    rows = [n for n, _ in sections if re.search(rf"Task {n}:", page_one)]
    if not (page_one.lstrip().startswith("PathLab write-up") and rows == [n for n, _ in sections]
            and len(re.findall(rf"Task {sections[0][0]}:", page_one)) >= 2 and "Code:" in page_one):
        fail(f"page 1 should hold the title, the overview of every task and the start of task {sections[0][0]}; "
             f"it reads: {' '.join(page_one.split())[:400]!r}")
    listed = subprocess.run(["pdfimages", "-list", str(pdf)], capture_output=True, text=True).stdout.splitlines()[2:]
    if len(listed) < len(parsed.images):
        fail(f"the PDF holds {len(listed)} images; the page shows {len(parsed.images)}")
    return {"images": len(parsed.images), "pages": pages, "pdf_images": len(listed), "sliders": sliders}


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--screenshots", help="write writeup-NAME.png here (docs/images)")
    parser.add_argument("--keep", help="keep the pages and PDFs here")
    parser.add_argument("--only", help="only these runs (reference, stubs, mixed), e.g. mixed")
    args = parser.parse_args()
    build = Path(args.build).resolve()
    browser_path = shutil.which("chromium") or shutil.which("google-chrome")
    missing = [t for t in ("tidy", "pdfinfo", "pdftotext", "pdfimages") if not shutil.which(t)]
    if not browser_path or missing:
        print(f"writeup: needs chromium, tidy and poppler-utils (missing: {missing or ['chromium']}); "
              "tools/packages.sh lists them", file=sys.stderr)
        return 1
    shots = Path(args.screenshots).resolve() if args.screenshots else None
    failures = []
    every = {int(p.name[:2]) for p in (ROOT / "tasks").iterdir() if re.fullmatch(r"\d\d-.*", p.name)}
    mixed = build / "tests" / "pathlab-mixed"
    drawn = set(pathlab_tasks.commit_sample("writeup", 4, "PATHLAB_WRITEUP_TASKS"))
    runs = [("reference", ["--tasks", ",".join(map(str, sorted(drawn)))], drawn, set()),
            ("stubs", ["--stubs"], set(), every)]
    print(f"  the reference on tasks {', '.join(map(str, sorted(drawn)))} (PATHLAB_WRITEUP_TASKS to choose)")
    if mixed.exists():
        runs.append(("mixed", ["--program", str(mixed)], {1, 2, 3}, every - {1, 2, 3}))
    if args.only:
        runs = [r for r in runs if r[0] in args.only.split(",")]
    with tempfile.TemporaryDirectory(prefix="pathlab-writeup-test-") as temp:
        out_root = Path(args.keep).resolve() if args.keep else Path(temp)
        browser = Chromium(browser_path)
        try:
            for name, flags, done, undone in runs:
                out = out_root / name
                run, seconds = make(build, out, *flags)
                if run.returncode != 0:
                    failures.append(f"{name}: tools/writeup exited {run.returncode}:\n{(run.stdout + run.stderr)[-2000:]}")
                    continue
                numbers = check_page(name, out / "writeup.html", out / "writeup.pdf", browser, done, undone, shots,
                                     failures)
                size = (out / "writeup.html").stat().st_size / 1e6
                print(f"  {name}: {seconds:.0f} s, page {size:.1f} MB with {numbers['images']} images "
                      f"({numbers['sliders']} sliders), PDF {numbers['pages']} pages, {numbers['pdf_images']} images")
        finally:
            browser.close()
    for f in failures:
        print("FAIL:", f)
    print(f"writeup: {'ok' if not failures else f'{len(failures)} failures'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
