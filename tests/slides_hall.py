#!/usr/bin/env python3
"""slides_hall.py OUT_DIR [REVIEW_DIR]: the HTML decks as a lecture hall's projector shows them.

Every lab*.html deck in OUT_DIR (and OUT_DIR/student) is opened in headless Chromium in a
1920x1080 frame, and every slide is measured where the browser drew it:

  - the slide is 16:9 and fills the frame (a 4:3 slide leaves bars at the sides);
  - every piece of text on it, captions and typeset math included, is drawn at 18 px or more,
    and so is every label of a diagram: an SVG diagram reaches the slide as an <img> (a data:
    URI), so each <text>'s font size is read from the SVG and scaled as the image is drawn
    (fitted in its box, object-fit: contain); an inline <svg> is measured where it is drawn;
  - a slide that shows a figure gives it a good share of the slide: the box around the
    pictures as drawn (not the boxes they are fitted in) is at least half the slide's height,
    or four fifths of its width (a row of side-by-side figures).

Text the slide hides (the lecturer's notes, shown in the speaker view) is not on the slide and
is not measured; it must be hidden there, and nowhere in the students' decks: every "Questions
for the room" slide keeps its answers in notes, and no phrase of any notes is in a students'
HTML or PDF (pdftotext), while each is in the lecturer's HTML (so the phrases are real ones). Exit 0: every slide passes; 1: a problem (each named: deck, slide, title, what
and how big); 77: no Chromium.
"""
import functools
import glob
import html
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading

WIDTH, HEIGHT = 1920, 1080
MIN_TEXT_PX = 18.0
MIN_FIGURE_HEIGHT = 0.5   # of the slide's height
MIN_FIGURE_WIDTH = 0.8    # of the slide's width, for a row of figures
# Slides made to show one figure (a diagram with its labels, or a row of renders): each must be in
# its deck with that many pictures, labels where it is a diagram, and the figure filling most of it.
FIGURE_SLIDES = {
    "lab4_pcf": {"Umbra and penumbra": (1, True), "Against the truth, the same light": (4, False)},
    "lab5_vsm": {"VSM beside PCF": (2, False), "Light bleeding": (2, False)},
    "lab6_cascades": {"A texel\u2019s footprint, seen": (1, True)},
}
MOST = 0.6                # "most of the slide": of its height, or of its width for a row

# Runs in the harness page; each deck is loaded in a same-origin iframe of 1920x1080.
MEASURE = r"""
function drawnBox(img, r) {
  // The picture inside an <img> fitted with object-fit: contain (otherwise the box itself).
  var fit = getComputedStyle(img).objectFit;
  var nw = img.naturalWidth, nh = img.naturalHeight;
  if (!(nw > 0 && nh > 0) || (fit !== 'contain' && fit !== 'scale-down')) return {x: r.left, y: r.top, w: r.width, h: r.height};
  var s = Math.min(r.width / nw, r.height / nh);
  if (fit === 'scale-down') s = Math.min(s, 1);
  var w = nw * s, h = nh * s;
  return {x: r.left + (r.width - w) / 2, y: r.top + (r.height - h) / 2, w: w, h: h};
}
function svgSize(svg) {
  var vb = (svg.getAttribute('viewBox') || '').trim().split(/[\s,]+/).map(Number);
  if (vb.length === 4 && vb[2] > 0 && vb[3] > 0) return [vb[2], vb[3]];
  return [parseFloat(svg.getAttribute('width')), parseFloat(svg.getAttribute('height'))];
}
function fontSizeOf(el) {
  // An SVG element's font size in user units: its own or the nearest ancestor's (attribute or style).
  var scale = 1;
  for (var e = el; e && e.getAttribute; e = e.parentNode) {
    var v = e.getAttribute('font-size');
    var st = (e.getAttribute('style') || '').match(/font-size\s*:\s*([0-9.]+)(px|%|em)?/);
    if (st) v = st[1] + (st[2] || '');
    if (v == null) continue;
    var m = String(v).match(/^([0-9.]+)\s*(px|%|em)?$/);
    if (!m) continue;
    if (m[2] === '%') { scale *= parseFloat(m[1]) / 100; continue; }
    if (m[2] === 'em') { scale *= parseFloat(m[1]); continue; }
    return scale * parseFloat(m[1]);
  }
  return scale * 16;
}
function svgLabels(text, drawnScale, out, where) {
  var doc = new DOMParser().parseFromString(text, 'image/svg+xml');
  var svg = doc.documentElement;
  if (!svg || svg.nodeName.toLowerCase() !== 'svg') return;
  var sz = svgSize(svg);
  Array.prototype.forEach.call(doc.querySelectorAll('text, tspan'), function (t) {
    // A <text> whose characters all sit in <tspan>s is measured by those.
    var own = Array.prototype.some.call(t.childNodes, function (n) { return n.nodeType === 3 && n.data.trim(); });
    if (!own) return;
    var px = fontSizeOf(t) * drawnScale(sz);
    out.push({px: px, text: t.textContent.trim().slice(0, 40), where: where});
  });
}
function decodeSvg(src) {
  var comma = src.indexOf(',');
  var head = src.slice(0, comma), body = src.slice(comma + 1);
  if (/;base64/.test(head)) {
    var bin = atob(body), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    return new TextDecoder('utf-8').decode(bytes);
  }
  return decodeURIComponent(body);
}
function measureDeck(win, doc) {
  var res = {slides: []};
  var secs = Array.prototype.slice.call(doc.querySelectorAll('body > section'));
  secs.forEach(function (s, i) {
    var sr = s.getBoundingClientRect();
    var k = sr.width / s.offsetWidth;          // CSS px to screen px (dzslides scales the body)
    var h1 = s.querySelector('h1');
    var slide = {index: i + 1, title: h1 ? h1.textContent.trim() : '', w: sr.width, h: sr.height,
                 text: [], labels: [], figures: 0, figW: 0, figH: 0, notes: 0, notesDrawn: 0};
    // The lecturer's notes (answers to the questions among them) are for the speaker view only.
    Array.prototype.forEach.call(s.querySelectorAll('.notes'), function (nt) {
      slide.notes++;
      if (nt.getClientRects().length && win.getComputedStyle(nt).visibility !== 'hidden') slide.notesDrawn++;
    });
    // Text: every text node with characters, at its element's computed size, where it is drawn.
    var walker = doc.createTreeWalker(s, NodeFilter.SHOW_TEXT);
    for (var n = walker.nextNode(); n; n = walker.nextNode()) {
      if (!n.data.replace(/[\s\u200b]/g, '')) continue;   // KaTeX's struts: zero-width spaces
      var el = n.parentElement;
      if (!el || el.closest('svg')) continue;                 // inline SVG: below
      if (el.closest('.katex-mathml')) continue;              // MathML for screen readers, clipped away
      if (el.getClientRects().length === 0) continue;        // not drawn (display: none)
      var cs = win.getComputedStyle(el);
      if (cs.visibility === 'hidden') continue;
      slide.text.push({px: parseFloat(cs.fontSize) * k, text: n.data.trim().slice(0, 40)});
    }
    // Figures: <img> (not KaTeX's), and inline <svg> outside math.
    var boxes = [];
    Array.prototype.forEach.call(s.querySelectorAll('img'), function (img) {
      if (img.closest('.katex') || img.getClientRects().length === 0) return;
      var b = drawnBox(img, img.getBoundingClientRect());
      boxes.push(b);
      var src = img.getAttribute('src') || '';
      if (/^data:image\/svg/.test(src)) {
        svgLabels(decodeSvg(src), function (sz) { return Math.min(b.w / sz[0], b.h / sz[1]); },
                  slide.labels, 'diagram');
      }
    });
    Array.prototype.forEach.call(s.querySelectorAll('svg'), function (svg) {
      if (svg.closest('.katex') || svg.parentElement.closest('svg') || svg.getClientRects().length === 0) return;
      var r = svg.getBoundingClientRect();
      boxes.push({x: r.left, y: r.top, w: r.width, h: r.height});
      Array.prototype.forEach.call(svg.querySelectorAll('text, tspan'), function (t) {
        var own = Array.prototype.some.call(t.childNodes, function (c) { return c.nodeType === 3 && c.data.trim(); });
        if (!own) return;
        var ctm = t.getScreenCTM();
        var sc = ctm ? Math.sqrt(ctm.a * ctm.a + ctm.b * ctm.b) : 1;
        slide.labels.push({px: parseFloat(win.getComputedStyle(t).fontSize) * sc,
                           text: t.textContent.trim().slice(0, 40), where: 'inline svg'});
      });
    });
    if (boxes.length) {
      var x0 = Math.min.apply(null, boxes.map(function (b) { return b.x; }));
      var y0 = Math.min.apply(null, boxes.map(function (b) { return b.y; }));
      var x1 = Math.max.apply(null, boxes.map(function (b) { return b.x + b.w; }));
      var y1 = Math.max.apply(null, boxes.map(function (b) { return b.y + b.h; }));
      slide.figures = boxes.length; slide.figW = x1 - x0; slide.figH = y1 - y0;
    }
    // Keep the report small: the smallest few of each.
    slide.text.sort(function (a, b) { return a.px - b.px; }); slide.text = slide.text.slice(0, 3);
    slide.labels.sort(function (a, b) { return a.px - b.px; }); slide.labels = slide.labels.slice(0, 3);
    res.slides.push(slide);
  });
  return res;
}
// The speaker view (key N, slides/tools/speaker-view.html), opened on the first slide with notes:
// its window is a frame of this page, read once the view has followed the deck.
function speakerCheck(w, d, done) {
  var secs = Array.prototype.slice.call(d.querySelectorAll('body > section'));
  var idx = secs.findIndex(function (s) { return s.querySelector('.notes'); });
  if (idx < 0) { done({error: 'no slide has notes'}); return; }
  var box = document.createElement('iframe');
  box.style.width = '900px'; box.style.height = '700px';
  document.body.appendChild(box);
  w.open = function () { return box.contentWindow; };
  if (w.Dz && w.Dz.setCursor) w.Dz.setCursor(idx + 1, 0);
  setTimeout(function () {
    w.dispatchEvent(new w.KeyboardEvent('keydown', {key: 'N'}));
    setTimeout(function () {
      var v = box.contentDocument;
      function text(id) { var e = v && v.getElementById(id); return e ? e.textContent : null; }
      var h1 = secs[idx].querySelector('h1');
      done({slide: idx + 1, count: secs.length, title: h1 ? h1.textContent.trim() : '',
            where: text('where'), notes: text('notes'), next: text('next'),
            expected: Array.prototype.map.call(secs[idx].querySelectorAll('.notes'),
                                               function (n) { return n.textContent; }).join(' '),
            notesPx: v && v.getElementById('notes') ? parseFloat(getComputedStyle(v.getElementById('notes')).fontSize) : 0});
      box.remove();
    }, 700);
  }, 100);
}
"""

HARNESS = """<!DOCTYPE html><html><head><style>body{margin:0} iframe{border:0;display:block}</style></head>
<body><pre id="hall"></pre><script>
MEASURE
var decks = DECKS, results = {};
function next(i) {
  if (i >= decks.length) {
    document.getElementById('hall').textContent = 'HALL' + 'JSON' + JSON.stringify(results) + 'HALL' + 'JSON';
    return;
  }
  var f = document.createElement('iframe');
  f.style.width = 'WIDTHpx'; f.style.height = 'HEIGHTpx';
  f.onload = function () {
    var w = f.contentWindow, d = f.contentDocument;
    // The frame's load event comes after its images (data: URIs); the fonts may come later.
    (d.fonts && d.fonts.ready ? d.fonts.ready : Promise.resolve()).then(function () {
      setTimeout(function () {
        try { if (w.Dz && w.Dz.onresize) w.Dz.onresize(); results[decks[i]] = measureDeck(w, d); }
        catch (e) { results[decks[i]] = {error: String(e), slides: []}; }
        if (/^student\//.test(decks[i])) { f.remove(); next(i + 1); return; }
        speakerCheck(w, d, function (sv) { results[decks[i]].speaker = sv; f.remove(); next(i + 1); });
      }, 50);
    });
  };
  f.src = decks[i];
  document.body.appendChild(f);
}
next(0);
</script></body></html>
"""

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars"]


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    return None


def words(text):
    return re.sub(r"\s+", " ", text).strip()


def html_text(path):
    t = open(path, encoding="utf-8").read()
    t = re.sub(r"<(script|style)\b.*?</\1>", " ", t, flags=re.S)
    t = re.sub(r'src="data:[^"]*"', " ", t)
    return words(html.unescape(re.sub(r"<[^>]+>", " ", t)))


def notes_phrases(md):
    """Each slide of a prepared deck (.NAME.lecturer.md): (title, its notes' lines), and plain
    phrases of the notes (math, code and list numbers left out) that the decks would show as text."""
    slides, title, inside = [], None, False
    for line in open(md, encoding="utf-8"):
        line = line.rstrip("\n")
        if line.startswith("# "):
            title = line[2:].strip()
            slides.append([title, []])
            continue
        if line.strip() in ("::: {.notes}", "::: notes"):
            inside = True
            continue
        if inside and line.strip() == ":::":
            inside = False
            continue
        if inside and slides:
            slides[-1][1].append(line)
    phrases = []
    for _, lines in slides:
        for line in lines:
            plain = re.sub(r"^\s*[0-9]+\.\s", " ", line.replace("*", ""))
            for part in re.split(r"\$[^$]*\$|`[^`]*`|[;:,.()?!\u2014\u2013]", plain):
                part = words(part)
                if len(part) >= 18 and len(part.split()) >= 3:
                    phrases.append(part)
    return slides, phrases


def notes_stay_with_the_lecturer(out):
    problems, checked = [], 0
    for md in sorted(glob.glob(os.path.join(out, ".lab[0-9]*.lecturer.md"))):
        name = os.path.basename(md)[1:-len(".lecturer.md")]
        slides, phrases = notes_phrases(md)
        for title, lines in slides:
            if title.lower().startswith("questions for the room") and not any(l.strip() for l in lines):
                problems.append(f"{name}: '{title}' has no lecturer's notes: its answers belong there")
        if not phrases:
            continue
        lecturer = html_text(os.path.join(out, name + ".html"))
        found = [p for p in phrases if p in lecturer]
        if len(found) < 0.8 * len(phrases):
            problems.append(f"{name}: only {len(found)} of {len(phrases)} phrases of the notes are in the lecturer's "
                            f"HTML (e.g. {next(p for p in phrases if p not in lecturer)!r}): the check reads them wrong")
        shown = {"HTML": html_text(os.path.join(out, "student", name + ".html"))}
        pdf = os.path.join(out, "student", name + ".pdf")
        if shutil.which("pdftotext") and os.path.isfile(pdf):
            r = subprocess.run(["pdftotext", "-layout", pdf, "-"], capture_output=True, text=True)
            shown["PDF"] = words(r.stdout)
        for kind, text in shown.items():
            leaked = [p for p in found if p in text]
            if leaked:
                problems.append(f"{name}: the students' {kind} shows the lecturer's notes: {leaked[0]!r}")
        checked += len(found)
    return problems, checked


def speaker_view_problems(deck, sv):
    """The lecturer's deck's speaker view, opened with key N on its first slide with notes: it
    names that slide, shows that slide's notes (all of them, nothing else) and the next title."""
    if not sv or sv.get("error"):
        return [f"{deck}: speaker view: {(sv or {}).get('error') or 'not measured'}"]
    where = f"{deck} speaker view on slide {sv['slide']} ({sv['title'][:40]})"
    if sv["where"] is None:
        return [f"{where}: key N opened no speaker view"]
    problems = []
    if not words(sv["where"]).startswith(f"{sv['slide']} / {sv['count']} {words(sv['title'])}"):
        problems.append(f"{where}: its heading says {sv['where']!r}")
    if not words(sv["expected"]) or words(sv["notes"]) != words(sv["expected"]):
        problems.append(f"{where}: shows {words(sv['notes'])[:80]!r}, not the slide's notes "
                        f"{words(sv['expected'])[:80]!r}")
    if not (sv["next"] or "").startswith(("Next: ", "Last slide")):
        problems.append(f"{where}: no next slide: {sv['next']!r}")
    if sv["notesPx"] < MIN_TEXT_PX:
        problems.append(f"{where}: notes drawn at {sv['notesPx']:.0f} px, under {MIN_TEXT_PX:.0f}")
    return problems


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: slides_hall.py OUT_DIR")
    out = sys.argv[1]
    exe = chromium()
    if not exe:
        print("slides-hall: SKIPPED: no Chromium")
        sys.exit(77)
    decks = [os.path.relpath(p, out) for p in sorted(glob.glob(os.path.join(out, "lab[0-9]*.html")))
             + sorted(glob.glob(os.path.join(out, "student", "lab[0-9]*.html")))]
    if not decks:
        print(f"slides-hall: no HTML decks in {out}", file=sys.stderr)
        sys.exit(1)

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *a):
            pass
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=out))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    profile = tempfile.mkdtemp(prefix="slides-hall-")
    page = os.path.join(out, ".slides-hall.html")
    try:
        with open(page, "w", encoding="utf-8") as f:
            f.write(HARNESS.replace("MEASURE", MEASURE).replace("DECKS", json.dumps(decks))
                    .replace("WIDTH", str(WIDTH)).replace("HEIGHT", str(HEIGHT)))
        r = subprocess.run([exe] + FLAGS + [f"--window-size={WIDTH},{HEIGHT}", f"--user-data-dir={profile}",
                                            "--virtual-time-budget=600000", "--dump-dom",
                                            f"http://127.0.0.1:{httpd.server_address[1]}/.slides-hall.html"],
                           capture_output=True, text=True, timeout=900)
    finally:
        httpd.shutdown()
        shutil.rmtree(profile, ignore_errors=True)
        if os.path.exists(page):
            os.remove(page)
    m = re.search(r"HALLJSON(.*?)HALLJSON", r.stdout, re.S)
    if not m:
        print(f"slides-hall: the measurement did not finish in Chromium (exit {r.returncode}; "
              f"{r.stdout.strip()[-200:]!r}; {r.stderr.strip()[-300:]})", file=sys.stderr)
        sys.exit(1)
    results = json.loads(m.group(1).replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))
    problems = []
    for deck in decks:
        res = results.get(deck, {"error": "not measured", "slides": []})
        if res.get("error") or not res["slides"]:
            problems.append(f"{deck}: {res.get('error') or 'no slides'}")
            continue
        if not deck.startswith("student/"):
            problems += speaker_view_problems(deck, res.get("speaker"))
        smallest, figs, worst_fig = None, 0, None
        for s in res["slides"]:
            where = f"{deck} slide {s['index']} ({s['title'][:40]})"
            if s["h"] <= 0 or abs(s["w"] / s["h"] - 16 / 9) > 0.01:
                problems.append(f"{where}: drawn {s['w']:.0f}x{s['h']:.0f}, not 16:9")
            elif s["w"] < 0.98 * WIDTH and s["h"] < 0.98 * HEIGHT:
                problems.append(f"{where}: drawn {s['w']:.0f}x{s['h']:.0f}, it does not fill a {WIDTH}x{HEIGHT} screen")
            for t in s["text"] + s["labels"]:
                if smallest is None or t["px"] < smallest:
                    smallest = t["px"]
                if t["px"] < MIN_TEXT_PX - 0.05:
                    kind = "a diagram's label" if "where" in t else "text"
                    problems.append(f"{where}: {kind} at {t['px']:.1f} px (under {MIN_TEXT_PX:g}): {t['text']!r}")
                    break
            if s.get("notesDrawn"):
                problems.append(f"{where}: the lecturer's notes are drawn on the slide (they belong in the speaker view)")
            if deck.startswith("student") and s.get("notes"):
                problems.append(f"{where}: a students' deck carries the lecturer's notes")
            if s["figures"]:
                figs += 1
                hs, ws = s["figH"] / s["h"], s["figW"] / s["w"]
                if worst_fig is None or max(hs, ws) < worst_fig:
                    worst_fig = max(hs, ws)
                if hs < MIN_FIGURE_HEIGHT and ws < MIN_FIGURE_WIDTH:
                    problems.append(f"{where}: its figure is drawn {s['figW']:.0f}x{s['figH']:.0f}, "
                                    f"{100 * hs:.0f}% of the slide's height and {100 * ws:.0f}% of its width")
        name = os.path.basename(deck)[:-len(".html")]
        titles = {s["title"].replace("'", "\u2019"): s for s in res["slides"]}
        for title, (pictures, diagram) in FIGURE_SLIDES.get(name, {}).items():
            s = titles.get(title)
            if s is None:
                problems.append(f"{deck}: no slide '{title}' (its figure is checked here)")
                continue
            where = f"{deck} slide {s['index']} ({title})"
            if s["figures"] != pictures:
                problems.append(f"{where}: {s['figures']} pictures drawn, {pictures} expected")
                continue
            if diagram and not s["labels"]:
                problems.append(f"{where}: the diagram's labels were not found")
            hs, ws = s["figH"] / s["h"], s["figW"] / s["w"]
            if hs < MOST and not (pictures > 1 and ws >= 0.9):
                problems.append(f"{where}: its figure fills {100 * hs:.0f}% of the height, {100 * ws:.0f}% of the "
                                f"width: not most of the slide")
        print(f"slides-hall: {deck}: {len(res['slides'])} slides, smallest text {smallest or 0:.1f} px, "
              f"{figs} with figures" + (f" (least filled {100 * worst_fig:.0f}%)" if worst_fig is not None else ""))
    note_problems, phrases = notes_stay_with_the_lecturer(out)
    problems += note_problems
    print(f"slides-hall: {phrases} phrases of the lecturer's notes, in none of the students' decks")
    for p in problems:
        print(f"slides-hall: {p}", file=sys.stderr)
    if problems:
        print(f"slides-hall: {len(problems)} problem(s) at {WIDTH}x{HEIGHT}", file=sys.stderr)
        sys.exit(1)
    print(f"slides-hall: {len(decks)} decks pass at {WIDTH}x{HEIGHT}: 16:9, text and labels >= {MIN_TEXT_PX:g} px, "
          "figures fill their slides")


if __name__ == "__main__":
    main()
