// The page of the interactive Campbell report (src/writers/campbell_html.hpp): HTML, CSS and the script
// that draws the two Campbell panels with d3 (v3 API, Debian's libjs-d3) and animates the selected mode
// shape with three.js's camera and projection (Debian's libjs-three) on a 2D canvas, so the page needs
// no WebGL. Placeholders replaced by campbellHtml: @@TITLE@@, @@D3@@, @@THREE@@, @@DATA@@, @@OPTIONS@@.
#include "src/writers/campbell_html.hpp"

namespace whirl::detail {

const char* const kCampbellHtmlPage = R"WHIRLPAGE(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>@@TITLE@@</title>
<style>
body { font-family: sans-serif; margin: 12px; color: #222; }
h1 { font-size: 18px; margin: 4px 0 10px 0; }
#main { display: flex; flex-wrap: wrap; gap: 16px; }
#plots { flex: 0 0 auto; }
#side { flex: 1 1 380px; min-width: 360px; }
.panel .axis path, .panel .axis line { fill: none; stroke: #444; shape-rendering: crispEdges; }
.panel .axis text { font-size: 11px; }
.panel .grid line { stroke: #e4e4e4; }
.panel path.line { fill: none; stroke-width: 1.6px; }
.panel path.np { fill: none; stroke: #999; stroke-dasharray: 5 4; }
.panel text.np { fill: #777; font-size: 11px; }
.panel circle.pt { stroke: #fff; stroke-width: 0.8px; cursor: pointer; }
.panel circle.pt.selected { stroke: #000; stroke-width: 2.5px; }
.panel circle.unstable { fill: none; stroke: #d00; stroke-width: 2px; pointer-events: none; }
.panel line.zero { stroke: #d00; stroke-dasharray: 2 2; }
.hidden { display: none; }
#legend { display: flex; flex-wrap: wrap; gap: 4px 10px; max-width: 760px; font-size: 12px; margin-top: 6px; }
#legend .entry { cursor: pointer; user-select: none; }
#legend .entry.off { opacity: 0.35; text-decoration: line-through; }
#legend .swatch { display: inline-block; width: 14px; height: 4px; margin-right: 4px; vertical-align: middle; }
#tooltip { position: absolute; pointer-events: none; background: #fffff4; border: 1px solid #999; padding: 5px 7px;
           font-size: 12px; border-radius: 3px; display: none; max-width: 340px; }
#view { border: 1px solid #bbb; background: #fbfbfb; display: block; }
#controls { font-size: 12px; margin: 4px 0; }
#controls label { margin-right: 10px; }
#modeinfo { font-size: 12px; min-height: 3em; }
table { border-collapse: collapse; font-size: 12px; margin-top: 8px; }
td, th { border: 1px solid #ccc; padding: 2px 6px; text-align: right; }
th { background: #f0f0f0; }
td.text { text-align: left; }
.ambiguous { color: #b35900; }
</style>
</head>
<body>
<h1 id="title"></h1>
<div id="main">
  <div id="plots">
    <div id="freq" class="panel"></div>
    <div id="damp" class="panel"></div>
    <div id="legend"></div>
  </div>
  <div id="side">
    <canvas id="view" width="440" height="440"></canvas>
    <div id="controls">
      <button id="play">pause</button>
      <label>amplitude <input id="amplitude" type="range" min="0" max="100" value="30"></label>
      <label>phase <input id="phase" type="range" min="0" max="360" value="0"></label>
      <label>view <input id="azimuth" type="range" min="-180" max="180" value="-60"></label>
    </div>
    <div id="modeinfo">Click a point of the diagram to see its mode shape.</div>
    <table id="summary"></table>
    <table id="steady"></table>
  </div>
</div>
<div id="tooltip"></div>
<script>@@D3@@</script>
<script>@@THREE@@</script>
<script id="whirl-data" type="application/json">@@DATA@@</script>
<script id="whirl-options" type="application/json">@@OPTIONS@@</script>
<script>
"use strict";
(function () {
  var data = JSON.parse(document.getElementById("whirl-data").textContent);
  var opt = JSON.parse(document.getElementById("whirl-options").textContent);
  var points = data.points, lineNames = data.lines;
  document.title = data.title;
  document.getElementById("title").textContent = data.title;

  // Which mode of each point is on which line (the JSON names each mode's line).
  var lines = lineNames.map(function (name, i) {
    return { name: name, index: i, modes: points.map(function (p) {
      for (var k = 0; k < p.modes.length; ++k) if (p.modes[k].line === name) return k;
      return -1;
    }) };
  });
  var versusWind = opt.versus_wind_speed && points.every(function (p) { return p.wind_speed !== null; });
  function xOf(p) { return versusWind ? p.wind_speed : p.rpm; }
  function modeAt(line, i) { return line.modes[i] >= 0 ? points[i].modes[line.modes[i]] : null; }
  function shown(line) {
    var any = false, allFirstOrder = true;
    for (var i = 0; i < points.length; ++i) {
      var m = modeAt(line, i);
      if (!m) continue;
      any = true;
      if (!m.first_order) allFirstOrder = false;
    }
    if (!any || (allFirstOrder && !opt.first_order_lines)) return false;
    if (opt.max_freq_hz > 0) {
      var low = false;
      for (var j = 0; j < points.length; ++j) { var mm = modeAt(line, j); if (mm && mm.freq_hz <= opt.max_freq_hz) low = true; }
      return low;
    }
    return true;
  }
  var visible = lines.filter(shown);
  var color = d3.scale.category20();

  // ---- the two panels -------------------------------------------------------------------------------
  var W = 760, H = 300, margin = { top: 12, right: 20, bottom: 38, left: 58 };
  var xs = points.map(xOf);
  var x = d3.scale.linear().domain(d3.extent(xs)).range([0, W - margin.left - margin.right]);
  if (xs.length === 1) x.domain([xs[0] - 1, xs[0] + 1]);
  var fmax = 0, zmin = 0, zmax = 0;
  visible.forEach(function (l) { for (var i = 0; i < points.length; ++i) { var m = modeAt(l, i); if (!m) continue;
    fmax = Math.max(fmax, m.freq_hz); zmin = Math.min(zmin, 100 * m.damping_ratio); zmax = Math.max(zmax, 100 * m.damping_ratio); } });
  if (opt.max_freq_hz > 0) fmax = opt.max_freq_hz; else fmax *= 1.05;
  if (!(fmax > 0)) fmax = 1;
  var zpad = 0.05 * Math.max(zmax - zmin, 1);
  var panels = [
    { id: "#freq", label: "frequency [Hz]", value: function (m) { return m.freq_hz; }, domain: [0, fmax] },
    { id: "#damp", label: "damping ratio [%]", value: function (m) { return 100 * m.damping_ratio; },
      domain: [Math.min(zmin - zpad, 0), zmax + zpad] }
  ];
  var tooltip = d3.select("#tooltip");
  var selected = null;

  function fmt(v, n) { return v === null || v === undefined ? "–" : (+v).toPrecision(n || 4); }
  function dominant(m) {
    var e = [];
    for (var c in m.participation) if (m.participation[c] !== null) e.push([c, m.participation[c]]);
    e.sort(function (a, b) { return b[1] - a[1]; });
    return e.slice(0, 3).map(function (v) { return v[0] + " " + (100 * v[1]).toFixed(1) + " %"; }).join(", ");
  }
  function evidence(m) {
    var ev = m.name_evidence;
    if (!ev) return "";
    var s = "name share " + (100 * ev.share).toFixed(1) + " %";
    if (ev.runner_up) s += ", runner-up " + ev.runner_up + " " + (100 * ev.runner_up_share).toFixed(1) + " %";
    return ev.ambiguous ? "<span class='ambiguous'>ambiguous: " + s + "</span>" : s;
  }
  function describe(line, i) {
    var m = modeAt(line, i), p = points[i];
    return "<b>" + line.name + "</b> (" + m.name + ")<br>" +
      (versusWind ? "wind " + fmt(p.wind_speed) + " m/s, " : "") + "rotor " + fmt(p.rpm) + " rpm<br>" +
      "frequency " + fmt(m.freq_hz, 5) + " Hz (damped " + fmt(m.damped_freq_hz, 5) + " Hz)<br>" +
      "damping " + fmt(100 * m.damping_ratio, 4) + " %<br>" + evidence(m) + "<br>dominant: " + dominant(m);
  }

  panels.forEach(function (panel) {
    var y = d3.scale.linear().domain(panel.domain).range([H - margin.top - margin.bottom, 0]).nice();
    var svg = d3.select(panel.id).append("svg").attr("width", W).attr("height", H)
      .append("g").attr("transform", "translate(" + margin.left + "," + margin.top + ")");
    var iw = W - margin.left - margin.right, ih = H - margin.top - margin.bottom;
    svg.append("g").attr("class", "grid").selectAll("line").data(y.ticks(6)).enter().append("line")
      .attr("x1", 0).attr("x2", iw).attr("y1", y).attr("y2", y);
    svg.append("g").attr("class", "x axis").attr("transform", "translate(0," + ih + ")")
      .call(d3.svg.axis().scale(x).orient("bottom"));
    svg.append("g").attr("class", "y axis").call(d3.svg.axis().scale(y).orient("left").ticks(6));
    svg.append("text").attr("x", iw / 2).attr("y", ih + 32).attr("text-anchor", "middle").style("font-size", "12px")
      .text(versusWind ? "wind speed [m/s]" : "rotor speed [rpm]");
    svg.append("text").attr("transform", "rotate(-90)").attr("x", -ih / 2).attr("y", -44).attr("text-anchor", "middle")
      .style("font-size", "12px").text(panel.label);
    var clip = panel.id.substring(1) + "-clip";
    svg.append("clipPath").attr("id", clip).append("rect").attr("width", iw).attr("height", ih);
    var body = svg.append("g").attr("clip-path", "url(#" + clip + ")");
    if (panel.id === "#freq") {
      opt.harmonics.forEach(function (n) {
        var pts = points.map(function (p) { return [x(xOf(p)), y(n * p.rpm / 60)]; });
        pts.sort(function (a, b) { return a[0] - b[0]; });
        body.append("path").attr("class", "np").attr("d", d3.svg.line()(pts));
        var last = pts[pts.length - 1];
        svg.append("text").attr("class", "np").attr("x", Math.min(last[0], iw) - 4)
          .attr("y", Math.max(last[1], 10) - 3).attr("text-anchor", "end").text(n + "P");
      });
    } else {
      body.append("line").attr("class", "zero").attr("x1", 0).attr("x2", iw).attr("y1", y(0)).attr("y2", y(0));
    }
    visible.forEach(function (line) {
      var cls = "l" + line.index;
      var idx = d3.range(points.length).filter(function (i) { return modeAt(line, i); });
      idx.sort(function (a, b) { return xOf(points[a]) - xOf(points[b]); });
      body.append("path").attr("class", "line " + cls).style("stroke", color(line.index))
        .attr("d", d3.svg.line().x(function (i) { return x(xOf(points[i])); })
          .y(function (i) { return y(panel.value(modeAt(line, i))); })(idx));
      idx.forEach(function (i) {
        var m = modeAt(line, i), cx = x(xOf(points[i])), cy = y(panel.value(m));
        if (m.damping_ratio < 0 && !m.rigid_body)
          body.append("circle").attr("class", "unstable " + cls).attr("cx", cx).attr("cy", cy).attr("r", 6);
        body.append("circle").attr("class", "pt " + cls + " p" + i).attr("cx", cx).attr("cy", cy).attr("r", 3.2)
          .style("fill", color(line.index))
          .on("mouseover", function () {
            tooltip.style("display", "block").html(describe(line, i));
          })
          .on("mousemove", function () {
            tooltip.style("left", (d3.event.pageX + 14) + "px").style("top", (d3.event.pageY + 10) + "px");
          })
          .on("mouseout", function () { tooltip.style("display", "none"); })
          .on("click", function () { select(line, i); });
      });
    });
  });

  // Legend: a click toggles a line in both panels.
  visible.forEach(function (line) {
    var e = d3.select("#legend").append("span").attr("class", "entry").attr("data-line", line.index)
      .on("click", function () {
        var off = !d3.select(this).classed("off");
        d3.select(this).classed("off", off);
        d3.selectAll(".panel .l" + line.index).classed("hidden", off);
      });
    e.append("span").attr("class", "swatch").style("background", color(line.index));
    e.append("span").text(line.name);
  });

  // ---- tables: the input summary and the steady operating points -------------------------------------
  var summary = d3.select("#summary");
  summary.append("tr").append("th").attr("colspan", 2).text("input");
  (opt.summary || []).forEach(function (kv) {
    var tr = summary.append("tr");
    tr.append("td").attr("class", "text").text(kv[0]);
    tr.append("td").attr("class", "text").text(kv[1]);
  });
  var steady = d3.select("#steady");
  var rowsOf = (opt.steady_csv || "").split("\n").filter(function (l) { return l.trim().length > 0; });
  if (rowsOf.length > 1) {
    // steady.csv of `whirl steady` in the same folder: its columns as written.
    steady.append("tr").append("th").attr("colspan", 20).text("steady operating points (steady.csv)");
    rowsOf.forEach(function (l, r) {
      var tr = steady.append("tr");
      l.split(",").forEach(function (v) {
        var num = +v;
        (r === 0 ? tr.append("th") : tr.append("td")).text(r > 0 && v !== "" && isFinite(num) ? fmt(num, 4) : v);
      });
    });
  } else {
    var head = steady.append("tr");
    ["point", "rotor [rpm]", "wind [m/s]", "pitch [deg]", "valid"].forEach(function (h) { head.append("th").text(h); });
    points.forEach(function (p, i) {
      var tr = steady.append("tr");
      [i, fmt(p.rpm), fmt(p.wind_speed), fmt(p.pitch_deg), p.validity ? "no" : "yes"].forEach(function (v) { tr.append("td").text(v); });
    });
  }

  // ---- the mode shape: three.js camera and projection, drawn on a 2D canvas ---------------------------
  var canvas = document.getElementById("view"), ctx = canvas.getContext("2d");
  var camera = new THREE.PerspectiveCamera(35, canvas.width / canvas.height, 0.1, 1e5);
  var shape = null, playing = true, start = performance.now();
  window.whirlAnimation = { frames: 0, selected: null };

  // Ground-frame node motion of one body: R (body → ground) times the body-frame amplitudes.
  function groundMotion(b) {
    var R = b.R, out = [];
    for (var k = 0; k < b.amplitude.length; ++k) {
      var re = [0, 0, 0], im = [0, 0, 0];
      for (var c = 0; c < 3; ++c) {
        var a = b.amplitude[k][c], ph = b.phase_deg[k][c] * Math.PI / 180;
        for (var r = 0; r < 3; ++r) { re[r] += R[r][c] * a * Math.cos(ph); im[r] += R[r][c] * a * Math.sin(ph); }
      }
      out.push({ re: re, im: im });
    }
    return out;
  }
  function select(line, i) {
    var m = modeAt(line, i);
    d3.selectAll("circle.pt.selected").classed("selected", false);
    d3.selectAll("circle.pt.l" + line.index + ".p" + i).classed("selected", true);
    selected = { line: line, point: i };
    window.whirlAnimation.selected = line.name + " @ " + i;
    document.getElementById("modeinfo").innerHTML = describe(line, i) +
      (m.motion ? "" : "<br><i>no mode shape for this mode (Floquet harmonics, or not computed)</i>");
    shape = null;
    if (!m.motion) { draw(0); return; }
    var bodies = m.motion.bodies.map(function (b) {
      return { name: b.body, role: b.role || "", pos: b.position_m, d: groundMotion(b) };
    });
    var lo = [1e30, 1e30, 1e30], hi = [-1e30, -1e30, -1e30];
    bodies.forEach(function (b) { b.pos.forEach(function (p) { for (var c = 0; c < 3; ++c) { lo[c] = Math.min(lo[c], p[c]); hi[c] = Math.max(hi[c], p[c]); } }); });
    var size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1);
    shape = { bodies: bodies, centre: [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2], size: size,
              freq: m.damped_freq_hz > 0 ? m.damped_freq_hz : m.freq_hz };
    start = performance.now();
    playing = true;
    document.getElementById("play").textContent = "pause";
  }
  function project(p) {
    var v = new THREE.Vector3(p[0], p[1], p[2]).project(camera);
    return [(v.x + 1) / 2 * canvas.width, (1 - v.y) / 2 * canvas.height];
  }
  function draw(now) {
    ctx.fillStyle = "#fbfbfb";
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (!shape) { ctx.fillStyle = "#888"; ctx.fillText("no mode selected", 10, 20); return; }
    var az = +document.getElementById("azimuth").value * Math.PI / 180, c = shape.centre, dist = 2.6 * shape.size;
    // Ground z up; the camera circles the turbine at the view angle, a little above the hub.
    camera.up.set(0, 0, 1);
    camera.position.set(c[0] + dist * Math.cos(az), c[1] + dist * Math.sin(az), c[2] + 0.25 * dist);
    camera.lookAt(new THREE.Vector3(c[0], c[1], c[2]));
    camera.updateMatrixWorld();
    // One cycle every 2 s whatever the frequency; the phase slider adds its offset.
    var t = playing ? (now - start) / 2000 : 0;
    var theta = 2 * Math.PI * t + (+document.getElementById("phase").value) * Math.PI / 180;
    var scale = (+document.getElementById("amplitude").value) / 100 * 0.15 * shape.size;
    var cs = Math.cos(theta), sn = Math.sin(theta);
    var hub = null, top = null;
    shape.bodies.forEach(function (b) {
      var pts = b.pos.map(function (p, k) {
        var d = b.d[k];
        return project([p[0] + scale * (d.re[0] * cs - d.im[0] * sn), p[1] + scale * (d.re[1] * cs - d.im[1] * sn),
                        p[2] + scale * (d.re[2] * cs - d.im[2] * sn)]);
      });
      if (b.role === "hub") hub = pts[0];
      if (b.role === "tower") top = pts[pts.length - 1];
      ctx.strokeStyle = b.role === "blade" ? "#1f5fbf" : b.role === "tower" ? "#444" : "#b04020";
      ctx.fillStyle = ctx.strokeStyle;
      ctx.lineWidth = b.role === "tower" ? 3 : 2;
      if (pts.length === 1) { ctx.fillRect(pts[0][0] - 3, pts[0][1] - 3, 6, 6); return; }
      ctx.beginPath();
      ctx.moveTo(pts[0][0], pts[0][1]);
      for (var k = 1; k < pts.length; ++k) ctx.lineTo(pts[k][0], pts[k][1]);
      ctx.stroke();
    });
    if (hub && top) { ctx.strokeStyle = "#b04020"; ctx.lineWidth = 2; ctx.beginPath(); ctx.moveTo(top[0], top[1]); ctx.lineTo(hub[0], hub[1]); ctx.stroke(); }
    ctx.fillStyle = "#333";
    ctx.fillText(selected.line.name + "  " + fmt(shape.freq, 4) + " Hz", 10, 16);
  }
  function frame(now) {
    if (shape) { draw(now); window.whirlAnimation.frames += 1; }
    window.requestAnimationFrame(frame);
  }
  document.getElementById("play").addEventListener("click", function () {
    playing = !playing;
    this.textContent = playing ? "pause" : "play";
    start = performance.now();
  });
  ["amplitude", "phase", "azimuth"].forEach(function (id) {
    document.getElementById(id).addEventListener("input", function () { if (shape && !playing) draw(0); });
  });
  draw(0);
  window.requestAnimationFrame(frame);
})();
</script>
</body>
</html>
)WHIRLPAGE";

}  // namespace whirl::detail
