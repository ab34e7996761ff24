"use strict";
/*
 * The page of a rigid-block run (settlement, limit load, minimum
 * thickness): the data is written by the `report' output
 * (source/rigid_blocks/postprocess/report.cc).
 */
(() => {
  const D = Report.data;
  const S = D.summary;
  const el = Report.el;
  const MM = 1000; // m -> mm

  const statusClass = (status) =>
    status === "optimal" ? "" : (status === "mechanism" || status === "incompatible" ||
                                 status === "no_collapse" || status === "stands_at_smallest_factor") ? "warn" : "bad";

  function header() {
    Report.root.append(el("h1", {}, `masonry: ${S.analysis} analysis`));
    Report.root.append(el("p", {class: "subtitle"}, S.parameter_file || "",
                          S.masonry_version ? ` · masonry ${S.masonry_version}` : ""));
    const p = el("p", {}, el("span", {class: "status " + statusClass(S.status), id: "status",
                                      dataset: {key: "status", value: JSON.stringify(S.status)}}, S.status));
    if (S.interface_model) p.append(`joints: ${S.interface_model}`);
    Report.root.append(p);
    if (S.explanation) Report.root.append(el("p", {class: "explanation"}, S.explanation));
    if (S.error) Report.root.append(el("p", {class: "problem"}, S.error));
  }

  /** Entries whose name says they diagnose the status (any structure). */
  function diagnostics() {
    const keys = Object.keys(S).filter((k) => /diagnos|misfit|incompatib/i.test(k));
    if (!keys.length) return;
    const s = Report.section("Diagnostics", "diagnostics");
    for (const k of keys) {
      const v = S[k];
      s.append(el("h3", {}, k));
      const list = Array.isArray(v) ? v : [v];
      if (list.length && list.every((x) => x && typeof x === "object" && !Array.isArray(x))) {
        const columns = [...new Set(list.flatMap((x) => Object.keys(x)))];
        s.append(Report.table(columns, list.map((x, i) => columns.map((c) =>
          typeof x[c] === "number" ? Report.num(`${k}${Array.isArray(v) ? `[${i}]` : ""}.${c}`, x[c])
                                   : (x[c] === undefined ? "" : (typeof x[c] === "object" ? JSON.stringify(x[c]) : String(x[c])))))));
      } else {
        s.append(el("pre", {}, JSON.stringify(v, null, 1)));
      }
    }
  }

  function keyResults() {
    const s = Report.section("Results", "results");
    const rows = [];
    const add = (key, label, unit, scale) => {
      if (typeof S[key] === "number") rows.push([label, Report.num(key, S[key], unit, scale)]);
      else if (typeof S[key] === "string" && S[key] !== "") rows.push([label, S[key]]);
    };
    add("external_work", "work of the loads", "J");
    add("dissipation", "dissipation", "J");
    add("objective", "objective (work − dissipation)", "J");
    add("load_multiplier", "load multiplier λ", "");
    add("mechanism_scale", "mechanism scale", "");
    add("minimum_thickness", "minimum thickness", "m");
    add("minimum_thickness_factor", "minimum thickness factor", "");
    add("collapse_thickness_factor", "collapses at factor", "");
    add("bisection_steps", "bisection steps", "");
    add("max_settlement", "largest settlement", "mm", MM);
    add("total_weight", "total weight", "kN", 1e-3);
    add("n_blocks", "blocks", "");
    add("n_interfaces", "interfaces", "");
    add("n_contact_points", "contact points", "");
    add("n_cracks", "cracks (interfaces that open or slide)", "");
    add("n_hinges", "of which hinges", "");
    add("displacement_amplification", "amplification of the pictures", "");
    const lp = [];
    const addLp = (key, label, unit) => {
      if (typeof S[key] === "number") lp.push([label, Report.num(key, S[key], unit)]);
      else if (typeof S[key] === "string" && S[key] !== "") lp.push([label, S[key]]);
    };
    addLp("lp_solver", "solver");
    addLp("lp_rows", "rows");
    addLp("lp_columns", "columns");
    addLp("lp_nonzeros", "non-zeros");
    addLp("lp_solves", "solves");
    addLp("lp_iterations", "iterations");
    addLp("cpu_seconds_solve", "solve, CPU", "s");
    addLp("seconds_solve", "solve, wall", "s");
    addLp("seconds_geometry", "blocks, wall", "s");
    addLp("seconds_assembly", "assembly, wall", "s");
    addLp("lp_max_violation", "largest constraint violation", "");
    const grid = el("div", {class: "grid"});
    grid.append(el("div", {}, el("h3", {}, "Analysis"), Report.pairs(rows)));
    grid.append(el("div", {}, el("h3", {}, "Linear program"), Report.pairs(lp)));
    if (S.support_reactions && typeof S.support_reactions === "object") {
      const r = Object.entries(S.support_reactions).map(([label, f]) =>
        [label, ...[0, 1, 2].map((d) => Report.num(`support_reactions.${label}[${d}]`, f[d], "", 1e-3))]);
      grid.append(el("div", {}, el("h3", {}, "Support reactions (kN, on the vault)"),
                     Report.table(["support", "x", "y", "z"], r, [false, true, true, true])));
    }
    s.append(grid);
    if (S.lp_message) s.append(el("p", {class: "note"}, "LP solver: " + S.lp_message));
  }

  // ---------------------------------------------------------------- 3D view
  const B = D.blocks;
  const interfaces = D.interfaces || [];
  const cracks = interfaces.filter((i) => i.type !== "closed");
  const supports = interfaces.filter((i) => i.support !== undefined);
  const moves = (i) => {
    for (let k = 0; k < i.u2.length; ++k) if (i.u2[k] !== 0) return true;
    return false;
  };
  const settling = supports.filter(moves), fixed = supports.filter((i) => !moves(i));
  let largestOpening = 0;
  for (const c of cracks) largestOpening = Math.max(largestOpening, c.max_opening);

  /** Flat points p displaced by a * u, as x, y, z arrays. */
  const displaced = (p, u, a, x, y, z) => {
    for (let k = 0; k < p.length; k += 3) {
      x.push(p[k] + a * u[k]);
      y.push(p[k + 1] + a * u[k + 1]);
      z.push(p[k + 2] + a * u[k + 2]);
    }
  };
  const point = (arr, k) => [arr[3 * k], arr[3 * k + 1], arr[3 * k + 2]];

  /** Every trace's coordinates at the amplification a: {name: {x, y, z}}. */
  function geometry(a) {
    const g = {};
    g.blocks = {x: [], y: [], z: []};
    displaced(B.p, B.u, a, g.blocks.x, g.blocks.y, g.blocks.z);
    g.edges = {x: [], y: [], z: []};
    for (const line of B.edges) {
      for (const v of line) {
        g.edges.x.push(g.blocks.x[v]); g.edges.y.push(g.blocks.y[v]); g.edges.z.push(g.blocks.z[v]);
      }
      g.edges.x.push(null); g.edges.y.push(null); g.edges.z.push(null);
    }
    // cracks: the intrados and extrados lines of both sides, and the gaps
    // between them (quads of consecutive stations), coloured by opening
    g.lines = {x: [], y: [], z: [], c: []};
    g.gaps = {x: [], y: [], z: [], i: [], j: [], k: [], c: []};
    g.hinges = {x: [], y: [], z: [], text: []};
    for (const c of cracks) {
      const n = c.opening.length / 2;
      const side = (u, face) => {
        const out = [];
        for (let s = 0; s < n; ++s) {
          const q = 2 * s + face;
          const p = point(c.p, q), d = point(u, q);
          out.push([p[0] + a * d[0], p[1] + a * d[1], p[2] + a * d[2], c.opening[q] * MM]);
        }
        return out;
      };
      for (const face of [0, 1]) {
        const one = side(c.u1, face), two = side(c.u2, face);
        for (const line of [one, two]) {
          for (const q of line) { g.lines.x.push(q[0]); g.lines.y.push(q[1]); g.lines.z.push(q[2]); g.lines.c.push(q[3]); }
          g.lines.x.push(null); g.lines.y.push(null); g.lines.z.push(null); g.lines.c.push(0);
        }
        const base = g.gaps.x.length;
        for (const q of one.concat(two)) { g.gaps.x.push(q[0]); g.gaps.y.push(q[1]); g.gaps.z.push(q[2]); g.gaps.c.push(q[3]); }
        for (let s = 0; s + 1 < n; ++s) {
          g.gaps.i.push(base + s, base + s);
          g.gaps.j.push(base + s + 1, base + n + s + 1);
          g.gaps.k.push(base + n + s + 1, base + n + s);
        }
      }
      if (c.type === "hinge") {
        // the pivot: the middle station of the face that stays closed
        const face = c.intrados_opening > c.extrados_opening ? 1 : 0;
        const q = 2 * Math.floor(n / 2) + face;
        const p = point(c.p, q), d = point(c.u1, q);
        g.hinges.x.push(p[0] + a * d[0]); g.hinges.y.push(p[1] + a * d[1]); g.hinges.z.push(p[2] + a * d[2]);
        g.hinges.text.push(`hinge, interface ${c.index}: opens ${Report.format(c.max_opening * MM)} mm at the ` +
                           (face === 1 ? "intrados" : "extrados"));
      }
    }
    // supports: the middle line of each support joint at rest and, for a
    // settling one, moved with the ground
    const middle = (i, u, a2, out) => {
      const n = i.p.length / 6;
      for (let s = 0; s < n; ++s) {
        const p = point(i.p, 2 * s), q = point(i.p, 2 * s + 1);
        const d = point(u, 2 * s), e = point(u, 2 * s + 1);
        out.x.push((p[0] + q[0]) / 2 + a2 * (d[0] + e[0]) / 2);
        out.y.push((p[1] + q[1]) / 2 + a2 * (d[1] + e[1]) / 2);
        out.z.push((p[2] + q[2]) / 2 + a2 * (d[2] + e[2]) / 2);
      }
      out.x.push(null); out.y.push(null); out.z.push(null);
    };
    g.fixed = {x: [], y: [], z: []};
    for (const i of fixed) middle(i, i.u2, 0, g.fixed);
    g.rest = {x: [], y: [], z: []};
    g.moved = {x: [], y: [], z: []};
    // the prescribed motion at every station: a segment from rest to moved
    g.arrows = {x: [], y: [], z: []};
    for (const i of settling) {
      middle(i, i.u2, 0, g.rest);
      middle(i, i.u2, a, g.moved);
      const n = i.p.length / 6;
      for (let s = 0; s < n; ++s) {
        const d = point(i.u2, 2 * s), e = point(i.u2, 2 * s + 1);
        const p = point(i.p, 2 * s), q = point(i.p, 2 * s + 1);
        for (const f of [0, a]) {
          g.arrows.x.push((p[0] + q[0]) / 2 + f * (d[0] + e[0]) / 2);
          g.arrows.y.push((p[1] + q[1]) / 2 + f * (d[1] + e[1]) / 2);
          g.arrows.z.push((p[2] + q[2]) / 2 + f * (d[2] + e[2]) / 2);
        }
        g.arrows.x.push(null); g.arrows.y.push(null); g.arrows.z.push(null);
      }
    }
    return g;
  }

  function view3d() {
    const s = Report.section("Deformed blocks", "view");
    const a0 = D.amplification;
    const value = el("span", {id: "amplification-value"}, Report.format(a0));
    const slider = el("input", {type: "range", min: "0", max: "3", step: "0.05", value: "1",
                                id: "amplification", "aria-label": "amplification"});
    s.append(el("div", {class: "controls"},
                el("label", {for: "amplification"}, "displacements × "), value,
                slider,
                el("span", {class: "note"}, `(slider: 0 to 3 times ${Report.format(a0)}, the factor of the ` +
                   "VTU files; the colours are the displacements themselves)")));
    const div = el("div", {class: "plot plot3d", id: "view3d"});
    s.append(div);
    if (!D.has_solution) {
      s.append(el("p", {class: "note"}, "No solution: the blocks are drawn at rest" +
                    (settling.length ? ", with the prescribed motion of the settling supports." : ".")));
    }
    const g = geometry(a0);
    const magnitude = [];
    for (let k = 0; k < B.u.length; k += 3) {
      magnitude.push(MM * Math.hypot(B.u[k], B.u[k + 1], B.u[k + 2]));
    }
    const tri = [[], [], []];
    for (let k = 0; k < B.triangles.length; k += 3) {
      tri[0].push(B.triangles[k]); tri[1].push(B.triangles[k + 1]); tri[2].push(B.triangles[k + 2]);
    }
    const traces = [];
    const moving = []; // [trace index, geometry name]
    const add = (trace, name) => { if (name) moving.push([traces.length, name]); traces.push(trace); };
    add({type: "mesh3d", name: "blocks", showlegend: true, x: g.blocks.x, y: g.blocks.y, z: g.blocks.z,
         i: tri[0], j: tri[1], k: tri[2], intensity: magnitude, colorscale: "Viridis",
         cmin: 0, cmax: magnitude.reduce((m, v) => Math.max(m, v), 1e-9),
         colorbar: {title: {text: "|u| (mm)"}, x: 1.0, len: 0.75},
         lighting: {ambient: 0.55, diffuse: 0.75, specular: 0.05, roughness: 0.9},
         hovertemplate: "|u| = %{intensity:.3g} mm<extra>blocks</extra>"}, "blocks");
    add({type: "scatter3d", mode: "lines", name: "block edges", x: g.edges.x, y: g.edges.y, z: g.edges.z,
         line: {color: "rgb(40,40,40)", width: 1.5}, hoverinfo: "skip"}, "edges");
    if (cracks.length) {
      const top = Math.max(largestOpening * MM, 1e-12);
      add({type: "mesh3d", name: "crack gaps", showlegend: true, x: g.gaps.x, y: g.gaps.y, z: g.gaps.z,
           i: g.gaps.i, j: g.gaps.j, k: g.gaps.k, intensity: g.gaps.c, colorscale: Report.ylOrRdScale,
           cmin: 0, cmax: top, showscale: false, opacity: 0.95, hoverinfo: "skip"}, "gaps");
      add({type: "scatter3d", mode: "lines", name: "cracks (by opening)", x: g.lines.x, y: g.lines.y, z: g.lines.z,
           line: {color: g.lines.c, colorscale: Report.ylOrRdScale, cmin: 0, cmax: top, width: 6,
                  colorbar: {title: {text: "opening (mm)"}, x: 1.1, len: 0.75}},
           hovertemplate: "opening %{line.color:.3g} mm<extra>crack</extra>"}, "lines");
    }
    if (g.hinges.x.length) {
      add({type: "scatter3d", mode: "markers", name: "hinges (pivot)", x: g.hinges.x, y: g.hinges.y, z: g.hinges.z,
           text: g.hinges.text, hoverinfo: "text", marker: {symbol: "diamond", size: 5, color: "black"}}, "hinges");
    }
    if (fixed.length) {
      add({type: "scatter3d", mode: "lines", name: "fixed supports", x: g.fixed.x, y: g.fixed.y, z: g.fixed.z,
           line: {color: "rgb(90,90,90)", width: 9}, hoverinfo: "name"}, null);
    }
    if (settling.length) {
      add({type: "scatter3d", mode: "lines", name: "settling supports, at rest", x: g.rest.x, y: g.rest.y, z: g.rest.z,
           line: {color: "rgb(160,160,160)", width: 5, dash: "dash"}, hoverinfo: "name"}, null);
      add({type: "scatter3d", mode: "lines", name: "settling supports, moved", x: g.moved.x, y: g.moved.y, z: g.moved.z,
           line: {color: "rgb(230,120,0)", width: 9}, hoverinfo: "name"}, "moved");
      add({type: "scatter3d", mode: "lines", name: "prescribed motion (× amplification)",
           x: g.arrows.x, y: g.arrows.y, z: g.arrows.z, line: {color: "rgb(230,120,0)", width: 3},
           hoverinfo: "name"}, "arrows");
    }
    // look from the side that moves most; a strip (arch) face on
    const ys = g.blocks.y, xs = g.blocks.x, zs = g.blocks.z;
    const extent = (v) => v.reduce((m, x) => Math.max(m, x), -Infinity) - v.reduce((m, x) => Math.min(m, x), Infinity);
    const strip = extent(ys) < 0.5 * Math.max(extent(xs), extent(zs));
    let eye = {x: 1.3, y: -1.3, z: 0.8};
    if (strip) eye = {x: 0.35 * Math.sign(D.view[0] || 1), y: -1.9, z: 0.45};
    else if (D.view[0] || D.view[1]) eye = {x: 2.1 * D.view[0], y: 2.1 * D.view[1], z: 1.1};
    const layout = {margin: {l: 0, r: 0, t: 10, b: 0}, legend: {x: 0, y: 1},
                    scene: {aspectmode: "data", camera: {eye: eye},
                            xaxis: {title: {text: "x (m)"}}, yaxis: {title: {text: "y (m)"}},
                            zaxis: {title: {text: "z (m)"}}}};
    slider.addEventListener("input", () => {
      const a = a0 * Number(slider.value);
      value.textContent = Report.format(a);
      const h = geometry(a);
      Plotly.restyle(div, {x: moving.map(([, n]) => h[n].x), y: moving.map(([, n]) => h[n].y),
                           z: moving.map(([, n]) => h[n].z)}, moving.map(([t]) => t));
    });
    return Report.plot(div, traces, layout);
  }

  // ---------------------------------------------------------------- crack map
  function crackMap() {
    const s = Report.section("Crack map (developed intrados)", "crack-map");
    s.append(el("p", {class: "note"},
                "Each patch unrolled by the arc lengths of its intrados (s across, upwards; t along the vault; exact for " +
                "barrel vaults and arches): solid lines open at the intrados (visible from below), dashed ones " +
                "only at the extrados, dotted ones slide; colour: the largest opening. The same map is " +
                "crack_map.png, its numbers crack_map.csv."));
    const div = el("div", {class: "plot plot2d", id: "crackmap"});
    s.append(div);
    const traces = [];
    // t (along the vault) across the page, s (across, along the intrados) up
    const line = (points, out) => {
      for (let k = 0; k < points.length; k += 2) { out.x.push(points[k + 1]); out.y.push(points[k]); }
      out.x.push(null); out.y.push(null);
    };
    const outline = {x: [], y: []};
    for (const p of D.patches) line(p.outline, outline);
    traces.push({type: "scatter", mode: "lines", name: "patch edges", x: outline.x, y: outline.y,
                 line: {color: "black", width: 1.2}, hoverinfo: "skip"});
    const joints = {x: [], y: []};
    for (const i of interfaces) if (i.support === undefined) line(i.map, joints);
    if (joints.x.length) {
      traces.push({type: "scatter", mode: "lines", name: "joints", x: joints.x, y: joints.y,
                   line: {color: "rgb(170,170,170)", width: 1}, hoverinfo: "skip"});
    }
    const fixedLine = {x: [], y: []}, settlingLine = {x: [], y: []};
    for (const i of fixed) line(i.map, fixedLine);
    for (const i of settling) line(i.map, settlingLine);
    if (fixedLine.x.length) {
      traces.push({type: "scatter", mode: "lines", name: "fixed support", x: fixedLine.x, y: fixedLine.y,
                   line: {color: "rgb(90,90,90)", width: 6}, hoverinfo: "name"});
    }
    if (settlingLine.x.length) {
      traces.push({type: "scatter", mode: "lines", name: "settling support", x: settlingLine.x, y: settlingLine.y,
                   line: {color: "rgb(230,120,0)", width: 6}, hoverinfo: "name"});
    }
    const top = Math.max(largestOpening, 1e-30);
    const style = (c) => c.type === "slip" ? "dot" :
      (c.intrados_opening > D.tolerance ? "solid" : "dash");
    const styleName = {solid: "opens at the intrados", dash: "opens at the extrados only", dot: "slip"};
    const shown = new Set();
    const mid = {x: [], y: [], c: [], text: []};
    for (const c of cracks) {
      const xy = {x: [], y: []};
      line(c.map, xy);
      const st = style(c);
      traces.push({type: "scatter", mode: "lines", x: xy.x, y: xy.y, legendgroup: st, name: styleName[st],
                   showlegend: !shown.has(st), hoverinfo: "skip",
                   line: {color: Report.colour(Report.ylOrRd, Math.max(0, c.max_opening) / top), width: 4, dash: st}});
      shown.add(st);
      const m = Math.floor(c.map.length / 4);
      mid.x.push(c.map[2 * m + 1]); mid.y.push(c.map[2 * m]); mid.c.push(Math.max(0, c.max_opening) * MM);
      mid.text.push(`interface ${c.index}: ${c.type}, opening ${Report.format(c.max_opening * MM)} mm ` +
                    `(intrados ${Report.format(c.intrados_opening * MM)}, extrados ${Report.format(c.extrados_opening * MM)})`);
    }
    if (cracks.length) {
      traces.push({type: "scatter", mode: "markers", name: "crack (hover)", x: mid.x, y: mid.y, text: mid.text,
                   hoverinfo: "text", showlegend: false,
                   marker: {size: 7, color: mid.c, colorscale: Report.ylOrRdScale, cmin: 0, cmax: top * MM,
                            line: {color: "black", width: 0.5},
                            colorbar: {title: {text: "opening (mm)"}}}});
    }
    const annotations = D.patches.map((p) => {
      let sx = 0, sy = 0;
      for (let k = 0; k < 8; k += 2) { sx += p.outline[k] / 4; sy += p.outline[k + 1] / 4; }
      return {x: sy, y: sx, text: p.name, showarrow: false, font: {color: "rgb(120,120,120)", size: 11}};
    });
    const layout = {margin: {l: 60, r: 20, t: 10, b: 50}, annotations: annotations,
                    xaxis: {title: {text: "t, along the vault (m)"}, zeroline: false},
                    yaxis: {title: {text: "s, across, along the intrados (m)"}, scaleanchor: "x", zeroline: false},
                    legend: {orientation: "h", y: -0.18}};
    return Report.plot(div, traces, layout);
  }

  // ---------------------------------------------------------------- adaptation
  function adaptation() {
    const a = S.adaptation;
    if (!a || typeof a !== "object") return null;
    const s = Report.section("Adaptation of the blocks", "adaptation");
    const rows = [];
    for (const [k, v] of Object.entries(a)) {
      if (typeof v === "number") rows.push([k, Report.num(`adaptation.${k}`, v)]);
      else if (typeof v === "string") rows.push([k, v]);
    }
    s.append(Report.pairs(rows));
    let traces = null, xTitle = "";
    if (D.generations && D.generations.length) {
      // adaptation.csv: generation, evaluations, best, mean, seconds
      const g = D.generations;
      traces = [{type: "scatter", mode: "lines+markers", name: "best", x: g.map((r) => r[0]), y: g.map((r) => r[2])},
                {type: "scatter", mode: "lines", name: "mean", x: g.map((r) => r[0]), y: g.map((r) => r[3]),
                 line: {dash: "dot"}}];
      xTitle = "generation";
    } else if (Array.isArray(a.stages) && a.stages.length) {
      const st = a.stages.filter((r) => typeof r.fitness === "number");
      traces = [{type: "scatter", mode: "lines+markers", name: "fitness", x: st.map((r) => r.blocks),
                 y: st.map((r) => r.fitness)}];
      xTitle = "blocks";
    }
    if (!traces) return null;
    const div = el("div", {class: "plot plot2d", id: "convergence"});
    s.append(div);
    return Report.plot(div, traces, {margin: {l: 70, r: 20, t: 10, b: 50},
                                     xaxis: {title: {text: xTitle}}, yaxis: {title: {text: a.fitness || "fitness"}}});
  }

  function crackList() {
    if (!Array.isArray(S.cracks) || !S.cracks.length) return;
    const s = Report.section(`Crack list (${S.cracks.length})`, "cracks");
    const byIndex = new Map(interfaces.map((i) => [i.index, i]));
    const rows = S.cracks.map((c, k) => {
      const i = byIndex.get(c.interface);
      const opens = !i ? "" : (i.intrados_opening > D.tolerance ? (i.extrados_opening > D.tolerance ? "both" : "intrados")
                                                                 : (i.extrados_opening > D.tolerance ? "extrados" : "—"));
      return [String(c.interface), c.type, opens, Report.num(`cracks[${k}].max_opening`, c.max_opening, "", MM),
              Report.num(`cracks[${k}].relative_rotation`, c.relative_rotation),
              String(c.first_block), String(c.second),
              c.position.map((x, d) => Report.num(`cracks[${k}].position[${d}]`, x)).reduce(
                (span, n, d) => { if (d) span.append(", "); span.append(n); return span; }, el("span"))];
    });
    s.append(el("div", {class: "scroll"},
                Report.table(["interface", "type", "opens at", "opening (mm)", "rotation (rad)", "block", "with",
                              "position (m)"], rows, [true, false, false, true, true, true, false, false])));
  }

  Report.start(async () => {
    header();
    diagnostics();
    keyResults();
    await view3d();
    await crackMap();
    await adaptation();
    crackList();
    Report.section("Summary", "all").append(Report.allEntries(S));
  });
})();
