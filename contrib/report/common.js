"use strict";
/*
 * The shared part of masonry's report pages (report.html): unpacking the
 * embedded plotly.js, number formatting, tables and plots. The page's own
 * script (rigid_blocks.js, wallette.js) follows this one and calls
 * Report.start(build).
 *
 * Every number taken from summary.json is shown through Report.num(),
 * which keeps the exact value and its path in the summary in data-value
 * and data-key (and the factor of a unit conversion in data-scale), so
 * that a test can compare the page with summary.json.
 */
const Report = (() => {
  const R = {};
  R.data = JSON.parse(document.getElementById("report-data").textContent);
  R.root = document.getElementById("report");

  /** Unpack the gzip-compressed plotly.js embedded in the page. */
  R.loadPlotly = async () => {
    if (typeof DecompressionStream === "undefined") {
      throw new Error("this browser cannot unpack the plotting library embedded in the page " +
                      "(no DecompressionStream: use Chrome or Edge 80, Firefox 113, Safari 16.4 or later)");
    }
    const text64 = document.getElementById("plotly-gzip").textContent.trim();
    const binary = atob(text64);
    const bytes = new Uint8Array(binary.length);
    for (let k = 0; k < binary.length; ++k) bytes[k] = binary.charCodeAt(k);
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    const code = await new Response(stream).text();
    const script = document.createElement("script");
    script.textContent = code;
    document.head.appendChild(script);
    if (typeof window.Plotly === "undefined") throw new Error("plotly.js did not load");
  };

  /** An element with attributes and children (text or nodes). */
  R.el = (tag, attributes, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes || {})) {
      if (v === undefined || v === null) continue;
      if (k === "class") e.className = v;
      else if (k === "dataset") Object.assign(e.dataset, v);
      else e.setAttribute(k, v);
    }
    for (const c of children) {
      if (c === undefined || c === null) continue;
      e.append(c instanceof Node ? c : String(c));
    }
    return e;
  };

  /** A number as shown: integers in full, others to 6 significant digits. */
  R.format = (x) => {
    if (typeof x !== "number") return String(x);
    if (Number.isInteger(x)) return String(x);
    const a = Math.abs(x);
    if (a !== 0 && (a < 1e-3 || a >= 1e7)) {
      return x.toExponential(5).replace(/\.?0+e/, "e").replace("e+", "e");
    }
    return String(Number(x.toPrecision(6)));
  };

  /**
   * A number of the summary at @p key (a path such as "cracks[2].max_opening"),
   * shown times @p scale with @p unit.
   */
  R.num = (key, value, unit, scale) => {
    const s = scale === undefined ? 1 : scale;
    const shown = typeof value === "number" ? R.format(value * s) : String(value);
    const span = R.el("span", {class: "num", dataset: {key: key, value: JSON.stringify(value)}}, shown);
    if (s !== 1) span.dataset.scale = String(s);
    if (!unit) return span;
    return R.el("span", {}, span, R.el("span", {class: "unit"}, unit));
  };

  /** A section with a heading, appended to the page. */
  R.section = (title, id) => {
    const s = R.el("section", {id: id});
    s.append(R.el("h2", {}, title));
    R.root.append(s);
    return s;
  };

  /** A two-column table of [label, value] rows. */
  R.pairs = (rows) => {
    const t = R.el("table");
    for (const [label, value] of rows) {
      t.append(R.el("tr", {}, R.el("th", {}, label), R.el("td", {class: "n"}, value)));
    }
    return t;
  };

  /** A table with a header row; @p rows are arrays of cells. */
  R.table = (header, rows, numeric) => {
    const t = R.el("table");
    t.append(R.el("tr", {}, ...header.map((h, k) => R.el("th", {class: numeric && numeric[k] ? "n" : null}, h))));
    for (const row of rows) {
      t.append(R.el("tr", {}, ...row.map((c, k) => R.el("td", {class: numeric && numeric[k] ? "n" : null}, c))));
    }
    return t;
  };

  /** Every entry of @p summary: numbers through num(), the rest as JSON. */
  R.allEntries = (summary) => {
    const rows = [];
    for (const [k, v] of Object.entries(summary)) {
      let shown;
      if (typeof v === "number") shown = R.num(k, v);
      else if (typeof v === "string" || typeof v === "boolean") shown = String(v);
      else shown = R.el("pre", {}, JSON.stringify(v, null, 1).slice(0, 20000));
      rows.push([k, shown]);
    }
    const d = R.el("details", {}, R.el("summary", {}, `every entry of summary.json (${rows.length})`),
                   R.el("div", {class: "scroll"}, R.pairs(rows)));
    return d;
  };

  /** A plot; resolves once drawn, and marks the element for tests. */
  R.plot = (element, traces, layout, config) => {
    element.dataset.expectedTraces = String(traces.length);
    return Plotly.newPlot(element, traces, layout,
                          Object.assign({responsive: true, displaylogo: false}, config || {}))
      .then(() => {
        element.dataset.traces = String(element.data.length);
        element.dataset.rendered = "1";
      });
  };

  /** Colour of value @p t in [0, 1] on a two-colour ramp list. */
  R.colour = (scale, t) => {
    const x = Math.min(1, Math.max(0, t));
    for (let k = 1; k < scale.length; ++k) {
      if (x <= scale[k][0]) {
        const [a, ca] = scale[k - 1], [b, cb] = scale[k];
        const f = b > a ? (x - a) / (b - a) : 0;
        const mix = ca.map((c, i) => Math.round(c + f * (cb[i] - c)));
        return `rgb(${mix[0]},${mix[1]},${mix[2]})`;
      }
    }
    const c = scale[scale.length - 1][1];
    return `rgb(${c[0]},${c[1]},${c[2]})`;
  };
  /** Plotly's YlOrRd, as [position, rgb] for R.colour() and as a colorscale. */
  R.ylOrRd = [[0, [255, 237, 160]], [0.25, [254, 178, 76]], [0.5, [253, 141, 60]],
              [0.75, [227, 26, 28]], [1, [128, 0, 38]]];
  R.ylOrRdScale = R.ylOrRd.map(([p, c]) => [p, `rgb(${c[0]},${c[1]},${c[2]})`]);

  /** Load plotly.js, then build the page; problems are shown and logged. */
  R.start = (build) => {
    R.loadPlotly()
      .then(() => {
        const loading = document.getElementById("loading");
        if (loading) loading.remove();
        return build();
      })
      .then(() => { document.body.dataset.ready = "1"; })
      .catch((error) => {
        R.root.append(R.el("p", {class: "problem"}, "The report could not be drawn: " + error.message));
        document.body.dataset.ready = "error";
        console.error(error);
      });
  };
  return R;
})();
