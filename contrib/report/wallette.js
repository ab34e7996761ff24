"use strict";
/*
 * The page of a wallette run: the data is written from the run's files by
 * the installed script wallette_report.py.
 */
(() => {
  const D = Report.data;
  const S = D.summary;
  const el = Report.el;
  const MPA = 1e-6;

  function header() {
    Report.root.append(el("h1", {}, "masonry: wallette analysis"));
    Report.root.append(el("p", {class: "subtitle"}, S.parameter_file || "",
                          S.masonry_version ? ` · masonry ${S.masonry_version}` : ""));
    const ok = S.status === "completed";
    Report.root.append(el("p", {}, el("span", {class: "status" + (ok ? "" : " bad"), id: "status",
                                               dataset: {key: "status", value: JSON.stringify(S.status)}}, S.status)));
    if (S.error) Report.root.append(el("p", {class: "problem"}, S.error));
    if (S.explanation) Report.root.append(el("p", {class: "explanation"}, S.explanation));
  }

  function keyResults() {
    const s = Report.section("Results", "results");
    const rows = [];
    const add = (key, label, unit, scale) => {
      if (typeof S[key] === "number") rows.push([label, Report.num(key, S[key], unit, scale)]);
      else if (typeof S[key] === "string" && S[key] !== "") rows.push([label, S[key]]);
    };
    add("peak_stress", "peak stress", "MPa", MPA);
    add("strain_at_peak", "strain at the peak", "");
    add("initial_modulus", "initial modulus", "MPa", MPA);
    add("final_stress", "final stress", "MPa", MPA);
    add("cycles", "cycles", "");
    add("external_work", "work of the platen", "J");
    add("deleted_cells", "deleted cells", "");
    add("height", "height", "m");
    add("length", "length", "m");
    add("thickness", "thickness", "m");
    add("gross_area", "gross area", "m²");
    const solver = [];
    const addSolver = (key, label, unit) => {
      if (typeof S[key] === "number") solver.push([label, Report.num(key, S[key], unit)]);
    };
    addSolver("steps", "steps");
    addSolver("newton_iterations", "Newton iterations");
    addSolver("cut_backs", "cut-backs");
    addSolver("linear_solves", "linear solves");
    addSolver("factorisations", "factorisations");
    addSolver("seconds", "wall time of the analysis", "s");
    const grid = el("div", {class: "grid"});
    grid.append(el("div", {}, el("h3", {}, "Wallette"), Report.pairs(rows)));
    if (solver.length) grid.append(el("div", {}, el("h3", {}, "Solver"), Report.pairs(solver)));
    s.append(grid);
  }

  // ---------------------------------------------------------------- 3D view
  const steps = D.steps || [];
  const damages = steps.length ? Object.keys(steps[0].values) : [];
  /** The colour of a face: the largest of the chosen damages. */
  const faceValues = (step, field) => {
    const names = field === "largest damage" ? damages : [field];
    const n = step.quads.length / 4;
    const out = new Array(n).fill(0);
    for (const name of names) {
      const v = step.values[name] || [];
      for (let f = 0; f < n; ++f) out[f] = Math.max(out[f], v[f] || 0);
    }
    return out;
  };

  const P = D.positions || [];
  const unit = D.displacement_unit || 1;

  function geometry(step, a, field) {
    const x = [], y = [], z = [];
    for (let n = 0; n < step.v.length; ++n) {
      const p = 3 * step.v[n], m = 3 * n;
      x.push(P[p] + a * unit * step.u[m]);
      y.push(P[p + 1] + a * unit * step.u[m + 1]);
      z.push(P[p + 2] + a * unit * step.u[m + 2]);
    }
    const i = [], j = [], k = [], c = [];
    const value = faceValues(step, field);
    for (let f = 0; f < step.quads.length / 4; ++f) {
      const q = step.quads.slice(4 * f, 4 * f + 4);
      i.push(q[0], q[0]); j.push(q[1], q[2]); k.push(q[2], q[3]);
      c.push(value[f], value[f]);
    }
    const edges = {x: [], y: [], z: []};
    for (let f = 0; f < step.quads.length / 4; ++f) {
      for (const v of [0, 1, 2, 3, 0]) {
        const q = step.quads[4 * f + v];
        edges.x.push(x[q]); edges.y.push(y[q]); edges.z.push(z[q]);
      }
      edges.x.push(null); edges.y.push(null); edges.z.push(null);
    }
    const joints = {x: [], y: [], z: [], c: []};
    const J = step.joints;
    if (J) {
      for (let q = 0; q < J.opening.length; ++q) {
        for (const v of [0, 1, 2, 3, 0]) {
          const n = 4 * q + v, p = 3 * J.v[n], m = 3 * n;
          joints.x.push(P[p] + a * unit * J.u[m]); joints.y.push(P[p + 1] + a * unit * J.u[m + 1]);
          joints.z.push(P[p + 2] + a * unit * J.u[m + 2]); joints.c.push(J.opening[q] * 1e3);
        }
        joints.x.push(null); joints.y.push(null); joints.z.push(null); joints.c.push(0);
      }
    }
    return {x, y, z, i, j, k, c, edges, joints};
  }

  let curveDiv = null;
  const markerOf = (step) => {
    // the converged step of the curve at this output: the last one whose
    // strain is the output's (the curve's strain column, to its precision)
    const c = D.curve;
    let best = 0, distance = Infinity;
    for (let k = 0; k < c.strain.length; ++k) {
      const d = Math.abs(c.strain[k] - step.strain);
      if (d <= distance) { distance = d; best = k; }
    }
    return {x: [c.strain[best]], y: [c.stress_Pa[best] * MPA]};
  };

  function view3d() {
    const s = Report.section("The wallette at an output step", "view");
    if (!steps.length) {
      s.append(el("p", {class: "note"}, "No fields were written (Write VTU = false): no 3D view."));
      return null;
    }
    const a0 = D.amplification;
    const stepSlider = el("input", {type: "range", min: "0", max: String(steps.length - 1), step: "1",
                                    value: String(steps.length - 1), id: "output-step", "aria-label": "output step"});
    const stepLabel = el("span", {id: "output-step-value"});
    const ampSlider = el("input", {type: "range", min: "0", max: "3", step: "0.05", value: "1",
                                   id: "amplification", "aria-label": "amplification"});
    const ampLabel = el("span", {id: "amplification-value"}, Report.format(a0));
    const choice = el("select", {id: "field"}, ...["largest damage", ...damages].map((d) => el("option", {value: d}, d)));
    s.append(el("div", {class: "controls"},
                el("label", {for: "output-step"}, "output step "), stepSlider, stepLabel,
                el("label", {for: "amplification"}, "displacements × "), ampLabel, ampSlider,
                el("label", {for: "field"}, "colour: "), choice));
    const div = el("div", {class: "plot plot3d", id: "view3d"});
    s.append(div);
    s.append(el("p", {class: "note"}, "Cells coloured by damage (the largest of the laws' damages, or the " +
                  "one chosen), deleted cells hidden; joints whose normal opening exceeds " +
                  `${Report.format(D.open_joint * 1e3)} mm drawn by their opening.`));
    const current = () => steps[Number(stepSlider.value)];
    const describe = (st) => `strain ${Report.format(st.strain)}, ${st.deleted} of ${st.cells} cells deleted` +
      (st.joints ? `, ${st.joints.opening.length} of ${st.joints.n_joints} joint faces open` : "");
    stepLabel.textContent = describe(current());
    const g = geometry(current(), a0, "largest damage");
    const traces = [
      {type: "mesh3d", name: "cells", showlegend: true, x: g.x, y: g.y, z: g.z, i: g.i, j: g.j, k: g.k,
       intensity: g.c, intensitymode: "cell", colorscale: Report.ylOrRdScale, cmin: 0, cmax: 1,
       colorbar: {title: {text: "damage"}, x: 1.0, len: 0.75}, flatshading: true,
       lighting: {ambient: 0.6, diffuse: 0.7, specular: 0.05},
       hovertemplate: "damage %{intensity:.3f}<extra>cell</extra>"},
      {type: "scatter3d", mode: "lines", name: "cell edges", x: g.edges.x, y: g.edges.y, z: g.edges.z,
       line: {color: "rgba(40,40,40,0.5)", width: 1}, hoverinfo: "skip"},
      {type: "scatter3d", mode: "lines", name: "open joints", x: g.joints.x, y: g.joints.y, z: g.joints.z,
       line: {color: g.joints.c.length ? g.joints.c : "rgb(20,60,200)", cmin: 0,
              colorscale: [[0, "rgb(158,202,225)"], [1, "rgb(8,48,107)"]],
              width: 5, colorbar: {title: {text: "opening (mm)"}, x: 1.12, len: 0.75}},
       hoverinfo: "name"}];
    const layout = {margin: {l: 0, r: 0, t: 10, b: 0}, legend: {x: 0, y: 1},
                    scene: {aspectmode: "data", camera: {eye: {x: 1.2, y: -1.7, z: 0.6}},
                            xaxis: {title: {text: "x (m)"}}, yaxis: {title: {text: "y (m)"}},
                            zaxis: {title: {text: "z (m)"}}}};
    const update = () => {
      const st = current();
      const a = a0 * Number(ampSlider.value);
      ampLabel.textContent = Report.format(a);
      stepLabel.textContent = describe(st);
      const h = geometry(st, a, choice.value);
      Plotly.restyle(div, {x: [h.x, h.edges.x, h.joints.x], y: [h.y, h.edges.y, h.joints.y],
                           z: [h.z, h.edges.z, h.joints.z], i: [h.i, null, null], j: [h.j, null, null],
                           k: [h.k, null, null], intensity: [h.c, null, null]}, [0, 1, 2]);
      Plotly.restyle(div, {"line.color": [h.joints.c.length ? h.joints.c : "rgb(20,60,200)"]}, [2]);
      if (curveDiv && curveDiv.data) {
        const m = markerOf(st);
        Plotly.restyle(curveDiv, {x: [m.x], y: [m.y]}, [curveDiv.data.length - 1]);
      }
    };
    stepSlider.addEventListener("input", update);
    ampSlider.addEventListener("input", update);
    choice.addEventListener("change", update);
    return Report.plot(div, traces, layout);
  }

  // ---------------------------------------------------------------- curve
  function curve() {
    const s = Report.section("Stress–strain curve", "curve");
    const c = D.curve;
    if (!c.strain || !c.strain.length) {
      s.append(el("p", {class: "note"}, "No curve.csv."));
      return null;
    }
    curveDiv = el("div", {class: "plot plot2d", id: "curveplot"});
    s.append(curveDiv);
    const traces = [{type: "scatter", mode: "lines", name: "stress–strain (platen)", x: c.strain,
                     y: c.stress_Pa.map((v) => v * MPA), line: {color: "rgb(31,119,180)", width: 1.6}}];
    if (D.cycles.length) {
      traces.push({type: "scatter", mode: "markers", name: "cycle peaks", x: D.cycles.map((r) => r.strain_at_peak),
                   y: D.cycles.map((r) => r.peak_stress_Pa * MPA), marker: {color: "rgb(214,39,40)", size: 7}});
    }
    const envelope = D.envelope.filter((r) => typeof r.envelope_stress_Pa === "number");
    if (envelope.length) {
      traces.push({type: "scatter", mode: "lines+markers", name: "envelope",
                   x: envelope.map((r) => r.envelope_strain), y: envelope.map((r) => r.envelope_stress_Pa * MPA),
                   line: {color: "rgb(44,160,44)", dash: "dash"}});
    }
    const m = steps.length ? markerOf(steps[steps.length - 1]) : {x: [], y: []};
    traces.push({type: "scatter", mode: "markers", name: "output step shown", x: m.x, y: m.y,
                 marker: {symbol: "circle-open", size: 14, color: "black", line: {width: 2}}});
    return Report.plot(curveDiv, traces, {margin: {l: 70, r: 20, t: 10, b: 50},
                                          xaxis: {title: {text: "strain (platen displacement / height)"}},
                                          yaxis: {title: {text: "stress (MPa)"}}, legend: {x: 0.7, y: 0.98}});
  }

  function tables() {
    if (D.cycles.length) {
      const s = Report.section(`Cycles (${D.cycles.length}), from cycles.csv`, "cycles");
      const columns = Object.keys(D.cycles[0]);
      s.append(el("div", {class: "scroll"}, Report.table(columns, D.cycles.map((r) => columns.map((k) =>
        typeof r[k] === "number" ? Report.format(r[k]) : String(r[k]))), columns.map(() => true))));
    }
    if (D.envelope.length) {
      const s = Report.section("Envelope, common and stability points, from envelope.csv", "envelope");
      const columns = Object.keys(D.envelope[0]);
      s.append(el("div", {class: "scroll"}, Report.table(columns, D.envelope.map((r) => columns.map((k) =>
        typeof r[k] === "number" ? Report.format(r[k]) : String(r[k]))), columns.map(() => true))));
    }
  }

  Report.start(async () => {
    header();
    keyResults();
    await curve();
    await view3d();
    tables();
    Report.section("Summary", "all").append(Report.allEntries(S));
  });
})();
