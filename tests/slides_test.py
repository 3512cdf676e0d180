#!/usr/bin/env python3
"""The lecture deck, checked as a user sees it: built from slides/lecture.md and the committed
figures (scripts/slides --deck), then opened in headless Chromium. Fails, naming what is wrong,
unless:
  - every slide is in the DOM and every image is embedded (a data: URI that decodes to a picture);
  - the maths is typeset (MathML elements, no TeX left in the text);
  - loading the deck makes no network request (Chromium's own net log);
  - screenshots of slides with a figure, maths, a table and a viewer screenshot are not blank;
  - nothing is cut off in the PDF: every page's content fits inside its 1280x720 page and its
    margins, as Chromium lays out the page the PDF is printed from (print.html, the same layout
    the PDF gets), and the PDF has one page per slide. Where pdftoppm is installed, the PDF's
    own pages are also rendered and their bottom margin band must be blank.
Usage: tests/slides_test.py OUT_DIR   (run from anywhere; the deck is written into OUT_DIR)
"""
import base64
import html.parser
import io
import json
import os
import re
import shutil
import subprocess
import sys

from PIL import Image, ImageStat

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHROMIUM = ["chromium", "--headless", "--no-sandbox", "--disable-gpu",
            "--disable-background-networking", "--disable-component-update", "--no-first-run",
            "--disable-sync", "--disable-default-apps", "--hide-scrollbars"]
# Chromium's own services, which it calls whatever page it shows (updates, time, spelling
# dictionaries, accounts): not the deck's requests.
BROWSER_HOSTS = re.compile(r"^https?://([a-z0-9-]+\.)*(google\.com|googleapis\.com|gvt1\.com|"
                           r"gstatic\.com)(:\d+)?/")
failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


class DeckParser(html.parser.HTMLParser):
    """Slides (section elements and how they nest), images, maths, and the visible text."""

    def __init__(self):
        super().__init__()
        self.depth = 0
        self.stacks = []  # per top-level section: the number of nested sections (0: a slide)
        self.images = []
        self.maths = 0
        self.displayed_maths = 0
        self.in_math = 0
        self.in_script = False
        self.text = []
        self.titles = []  # (top index, nested index or None, title)
        self.heading = None  # the text of the heading being read
        self.in_slides = False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "section" and self.in_slides:
            self.depth += 1
            if self.depth == 1:
                self.stacks.append(0)
            elif self.depth == 2:
                self.stacks[-1] += 1
        elif tag == "div" and "slides" in (attrs.get("class") or "").split():
            self.in_slides = True
        elif tag == "img":
            # reveal.js loads images near the current slide: the others still hold data-src.
            self.images.append(attrs.get("src") or attrs.get("data-src") or "")
        elif tag == "math":
            self.maths += 1
            self.displayed_maths += attrs.get("display") == "block"
            self.in_math += 1
        elif tag in ("script", "style"):
            self.in_script = True
        elif tag in ("h1", "h2") and self.stacks:
            nested = self.stacks[-1] - 1 if self.depth == 2 else None
            self.heading = (len(self.stacks) - 1, nested, [])

    def handle_endtag(self, tag):
        if tag == "section" and self.in_slides:
            self.depth -= 1
        elif tag == "math":
            self.in_math -= 1
        elif tag in ("script", "style"):
            self.in_script = False
        elif tag in ("h1", "h2") and self.heading:
            top, nested, words = self.heading
            self.titles.append((top, nested, " ".join("".join(words).split())))
            self.heading = None

    def handle_data(self, data):
        if self.heading:
            self.heading[2].append(data)
        if not self.in_math and not self.in_script:
            self.text.append(data)


def run(arguments, **kwargs):
    return subprocess.run(arguments, capture_output=True, text=True, timeout=120, **kwargs)


# Runs in print.html once its images are decoded: for every page box (the title, a section's
# title page, a slide), how far its content reaches below and right of the box's content area
# (inside the padding that is the page's margin), and its text. Written into the DOM as JSON.
MEASURE_PAGES = """
<script>
window.addEventListener("load", () => {
  const pages = document.querySelectorAll(
      "header#title-block-header, section.level1 > h1, section.level2");
  const report = [];
  for (const page of pages) {
    const box = page.getBoundingClientRect(), style = getComputedStyle(page);
    const bottom = box.bottom - parseFloat(style.paddingBottom);
    const right = box.right - parseFloat(style.paddingRight);
    let lowest = box.top, rightmost = box.left;
    for (const element of page.querySelectorAll("*")) {
      const r = element.getBoundingClientRect();
      if (r.width > 0 && r.height > 0) {
        lowest = Math.max(lowest, r.bottom);
        rightmost = Math.max(rightmost, r.right);
      }
    }
    report.push({title: page.textContent.trim().split("\\n")[0].slice(0, 70),
                 height: box.height, width: box.width,
                 below: lowest - bottom, beyond: rightmost - right});
  }
  const out = document.createElement("pre");
  out.id = "page-report";
  out.textContent = JSON.stringify(report);
  document.body.appendChild(out);
});
</script>
"""


def check_pages(out, pdf):
    """Nothing cut off: every page's content inside its page and margins, one PDF page each."""
    printed = os.path.join(out, "print.html")
    if not os.path.exists(printed):
        fail("scripts/slides --keep-print left no print.html to measure")
        return
    page = open(printed, encoding="utf-8").read()
    measured = os.path.join(out, "print-measured.html")
    with open(measured, "w", encoding="utf-8") as f:
        f.write(page.replace("</body>", MEASURE_PAGES + "</body>"))
    dom = run(CHROMIUM + ["--window-size=1280,720", "--virtual-time-budget=5000", "--dump-dom",
                          "file://" + measured]).stdout
    found = re.search(r'<pre id="page-report">(.*?)</pre>', dom, re.S)
    if not found:
        fail("the page layout could not be measured in print.html")
        return
    pages = json.loads(html.unescape(found.group(1)))
    for number, entry in enumerate(pages, 1):
        if round(entry["height"]) != 720 or round(entry["width"]) != 1280:
            fail(f"PDF page {number} ('{entry['title']}') is {entry['width']:.0f}x"
                 f"{entry['height']:.0f} px, not 1280x720")
        # Half a pixel of slack for sub-pixel layout; anything more is cut off or in the margin.
        if entry["below"] > 0.5:
            fail(f"PDF page {number} ('{entry['title']}'): content runs {entry['below']:.0f} px "
                 "into the bottom margin or off the page")
        if entry["beyond"] > 0.5:
            fail(f"PDF page {number} ('{entry['title']}'): content runs {entry['beyond']:.0f} px "
                 "into the right margin or off the page")
    # Chromium writes one page object per page.
    page_objects = len(re.findall(rb"/Type\s*/Page\b", open(pdf, "rb").read()))
    if page_objects != len(pages):
        fail(f"the PDF has {page_objects} pages, print.html {len(pages)} page boxes")
    print(f"{len(pages)} PDF pages measured, the lowest content "
          f"{max(entry['below'] for entry in pages):+.0f} px from the bottom margin")

    # The PDF itself, where a renderer is at hand: the bottom margin band must hold no ink.
    if shutil.which("pdftoppm"):
        rendered = os.path.join(out, "pages")
        os.makedirs(rendered, exist_ok=True)
        run(["pdftoppm", "-r", "24", "-png", pdf, os.path.join(rendered, "p")])
        images = sorted(os.listdir(rendered))
        if len(images) != len(pages):
            fail(f"pdftoppm rendered {len(images)} pages, print.html has {len(pages)}")
        for name in images:
            grey = Image.open(os.path.join(rendered, name)).convert("L")
            # The lowest 3/4 of the 40 px margin: 30 of 720 rows.
            band = grey.crop((0, grey.height - grey.height * 30 // 720, grey.width, grey.height))
            if band.getextrema()[0] < 200:
                fail(f"PDF page {name} has ink in its bottom margin")


def main():
    out = os.path.abspath(sys.argv[1])
    shutil.rmtree(out, ignore_errors=True)
    built = run([os.path.join(ROOT, "scripts/slides"), "--deck", "--keep-print", "--out", out])
    if built.returncode != 0:
        print(built.stdout, built.stderr)
        sys.exit("FAIL: scripts/slides --deck did not build the deck")
    deck = os.path.join(out, "lecture.html")
    pdf = os.path.join(out, "lecture.pdf")
    if not os.path.getsize(pdf) > 10000 or not open(pdf, "rb").read(5) == b"%PDF-":
        fail("the PDF is missing or empty")
    check_pages(out, pdf)

    # The DOM after reveal.js has run, and every network request Chromium made meanwhile.
    net_log = os.path.join(out, "net-log.json")
    dom = run(CHROMIUM + ["--virtual-time-budget=5000", f"--log-net-log={net_log}",
                          "--dump-dom", "file://" + deck]).stdout
    parser = DeckParser()
    parser.feed(dom)
    slides = sum(max(1, nested) for nested in parser.stacks)
    source = open(os.path.join(ROOT, "slides/lecture.md"), encoding="utf-8").read()
    expected = len(re.findall(r"^## ", source, re.M))
    if slides < expected:
        fail(f"{slides} slides in the deck, {expected} in slides/lecture.md")
    if not parser.images:
        fail("no images in the deck")
    for src in parser.images:
        if not src.startswith("data:image/"):
            fail(f"an image is not embedded: {src[:80]}")
            continue
        try:
            picture = Image.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1])))
            picture.load()
            if picture.width < 50 or picture.height < 50:
                fail(f"an embedded image is only {picture.width}x{picture.height}")
        except Exception as error:  # a broken image
            fail(f"an embedded image does not decode: {error}")
    displayed_maths = len(re.findall(r"\$\$", source)) // 2
    if parser.displayed_maths != displayed_maths:
        fail(f"{parser.displayed_maths} displayed formulas typeset, the source has {displayed_maths}")
    text = " ".join(parser.text)
    for leftover in (r"\int", r"\frac", "$$", r"\sum"):
        if leftover in text:
            fail(f"TeX left untypeset in the deck's text: {leftover}")

    if not os.path.exists(net_log):
        sys.exit("FAIL: Chromium wrote no net log, so network requests cannot be checked")
    log = open(net_log, encoding="utf-8").read()
    requests = sorted(set(re.findall(r'"(?:url|original_url)":"((?:https?|wss?|ftp)://[^"]+)"', log)))
    requests = [url for url in requests if not BROWSER_HOSTS.match(url)]
    if requests:
        fail(f"the deck made network requests: {requests[:5]}")

    # Screenshots of slides that show a figure, maths, a table and a viewer screenshot.
    wanted = ["Five stages, one renderer", "A pixel is an integral",
              "Measured at equal time", "Live: pathway view --demo nested-vs-4d",
              "The explosion, counted"]
    by_title = {title: (top, nested) for top, nested, title in parser.titles}
    for title in wanted:
        if title not in by_title:
            fail(f"no slide titled '{title}'")
            continue
        top, nested = by_title[title]
        anchor = f"#/{top}" + (f"/{nested}" if nested is not None else "")
        shot = os.path.join(out, f"slide-{top}-{nested or 0}.png")
        run(CHROMIUM + ["--window-size=1280,720", "--virtual-time-budget=3000",
                        f"--screenshot={shot}", "file://" + deck + anchor])
        if not os.path.exists(shot):
            fail(f"no screenshot of '{title}'")
            continue
        grey = Image.open(shot).convert("L")
        spread = ImageStat.Stat(grey).stddev[0]
        dark = sum(grey.histogram()[:200]) / (grey.width * grey.height)
        if spread < 10 or dark < 0.01:
            fail(f"the slide '{title}' looks blank (spread {spread:.1f}, dark share {dark:.3f})")
        print(f"slide '{title}' ({anchor}): spread {spread:.1f}, dark share {dark:.3f}, {shot}")

    print(f"{slides} slides, {len(parser.images)} embedded images, {parser.maths} formulas, "
          f"{len(requests)} network requests")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")


if __name__ == "__main__":
    main()
