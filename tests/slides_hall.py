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
is not measured. Exit 0: every slide passes; 1: a problem (each named: deck, slide, title, what
and how big); 77: no Chromium.
"""
import functools
import glob
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
                 text: [], labels: [], figures: 0, figW: 0, figH: 0};
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
        f.remove();
        next(i + 1);
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
            if s["figures"]:
                figs += 1
                hs, ws = s["figH"] / s["h"], s["figW"] / s["w"]
                if worst_fig is None or max(hs, ws) < worst_fig:
                    worst_fig = max(hs, ws)
                if hs < MIN_FIGURE_HEIGHT and ws < MIN_FIGURE_WIDTH:
                    problems.append(f"{where}: its figure is drawn {s['figW']:.0f}x{s['figH']:.0f}, "
                                    f"{100 * hs:.0f}% of the slide's height and {100 * ws:.0f}% of its width")
        print(f"slides-hall: {deck}: {len(res['slides'])} slides, smallest text {smallest or 0:.1f} px, "
              f"{figs} with figures" + (f" (least filled {100 * worst_fig:.0f}%)" if worst_fig is not None else ""))
    for p in problems:
        print(f"slides-hall: {p}", file=sys.stderr)
    if problems:
        print(f"slides-hall: {len(problems)} problem(s) at {WIDTH}x{HEIGHT}", file=sys.stderr)
        sys.exit(1)
    print(f"slides-hall: {len(decks)} decks pass at {WIDTH}x{HEIGHT}: 16:9, text and labels >= {MIN_TEXT_PX:g} px, "
          "figures fill their slides")


if __name__ == "__main__":
    main()
