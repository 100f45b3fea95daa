// The case viewer: draws each run of a case on a canvas, in the contact frame,
// and lets the reader rotate (drag) and zoom (wheel). It reads the runs from
// a <script type="application/json" class="case-data"> element and draws into
// the element just before it. It loads nothing: every page that uses it
// carries it inline. After drawing, it records on <body> what it drew
// (data-drawn: canvases, data-inked: painted pixels, data-svgs: SVGs with
// elements), so that a headless browser can tell a page that drew from a
// blank one; the page's error trap, in its <head>, records script errors on
// <html> (data-script-error).
(function () {
  "use strict";
  const colours = { A: "#2f6fd0", B: "#e07a1f", clipped: "#1f9a4a", broken: "#d0182b" };
  const size = 520;

  function dot(u, v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
  function cross(u, v) { return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]; }
  function add(u, v, s) { return [u[0] + s * v[0], u[1] + s * v[1], u[2] + s * v[2]]; }
  function scaled(u, s) { return [s * u[0], s * u[1], s * u[2]]; }
  function unit(u) { const l = Math.hypot(u[0], u[1], u[2]) || 1; return scaled(u, 1 / l); }
  function finite(u) { return u && u.every(function (x) { return typeof x === "number" && isFinite(x); }); }
  // Rotates u about the unit axis k by angle a (Rodrigues).
  function turned(u, k, a) {
    const c = Math.cos(a), s = Math.sin(a);
    return add(add(scaled(u, c), cross(k, u), s), k, dot(k, u) * (1 - c));
  }

  // The views of the SVG, in the same contact frame.
  function frameViews(run) {
    const n = run.normal, t1 = run.across1, t2 = run.across2;
    const turn = 35 * Math.PI / 180, tip = 25 * Math.PI / 180;
    const side = add(scaled(t1, Math.cos(turn)), t2, Math.sin(turn));
    const up = unit(add(scaled(n, Math.cos(tip)), cross(n, side), Math.sin(tip)));
    return {
      "along n": { right: t1, up: t2 },
      "across (t1)": { right: t1, up: n },
      "across (t2)": { right: t2, up: n },
      "oblique": { right: side, up: up },
    };
  }

  function smallerHull(run) {
    function spread(h) {
      let d = 0;
      for (const p of h.vertices) for (const q of h.vertices) d = Math.max(d, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
      return d;
    }
    return spread(run.a) <= spread(run.b) ? run.a : run.b;
  }

  function pointsOfInterest(run) {
    const points = smallerHull(run).vertices.slice();
    for (const c of run.contacts) { if (finite(c.a)) points.push(c.a); if (finite(c.b)) points.push(c.b); }
    return points.concat(run.clipped);
  }

  function View(run, canvas) {
    this.run = run;
    this.canvas = canvas;
    this.views = frameViews(run);
    this.set("oblique");
  }

  View.prototype.set = function (name) {
    this.right = this.views[name].right;
    this.up = this.views[name].up;
    this.fit();
    this.draw();
  };

  View.prototype.fit = function () {
    const points = pointsOfInterest(this.run);
    const depth = cross(this.right, this.up);
    let centre = [0, 0, 0];
    for (const p of points) centre = add(centre, p, 1 / points.length);
    let span = 0;
    for (const p of points) span = Math.max(span, Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]));
    this.centre = centre;
    this.zoom = 0.4 * size / (span || 1);
    this.depth = depth;
  };

  View.prototype.at = function (p) {
    const d = add(p, this.centre, -1);
    return [size / 2 + this.zoom * dot(d, this.right), size / 2 - this.zoom * dot(d, this.up)];
  };

  View.prototype.path = function (ctx, points, close) {
    ctx.beginPath();
    points.forEach(function (q, k) { if (k === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]); });
    if (close) ctx.closePath();
  };

  View.prototype.draw = function () {
    const run = this.run, ctx = this.canvas.getContext("2d"), self = this;
    const depth = cross(this.right, this.up);
    ctx.fillStyle = "#fcfcfc";
    ctx.fillRect(0, 0, size, size);
    const faces = [];
    ["A", "B"].forEach(function (which) {
      const hull = which === "A" ? run.a : run.b;
      hull.faces.forEach(function (loop, f) {
        let mean = [0, 0, 0];
        for (const i of loop) mean = add(mean, hull.vertices[i], 1 / loop.length);
        faces.push({ depth: dot(mean, depth), hull: which, face: f, loop: loop, vertices: hull.vertices });
      });
    });
    faces.sort(function (x, y) { return x.depth - y.depth; });
    for (const face of faces) {
      const reference = face.hull === run.referenceHull && face.face === run.referenceFace;
      const incident = face.hull !== run.referenceHull && face.face === run.incidentFace;
      this.path(ctx, face.loop.map(function (i) { return self.at(face.vertices[i]); }), true);
      ctx.globalAlpha = reference ? 0.4 : 0.08;
      ctx.fillStyle = colours[face.hull];
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.strokeStyle = colours[face.hull];
      ctx.lineWidth = reference || incident ? 2.2 : 0.8;
      ctx.setLineDash(incident ? [6, 3] : []);
      ctx.stroke();
    }
    ctx.setLineDash([]);
    if (run.clipped.length > 2) {
      this.path(ctx, run.clipped.map(function (p) { return self.at(p); }), true);
      ctx.strokeStyle = colours.clipped;
      ctx.lineWidth = 2;
      ctx.stroke();
    }
    let centre = [0, 0, 0], count = 0;
    run.contacts.forEach(function (c) {
      if (!finite(c.a) || !finite(c.b)) return;
      const a = self.at(c.a), b = self.at(c.b);
      self.path(ctx, [a, b], false);
      ctx.strokeStyle = "#222";
      ctx.lineWidth = 1.4;
      ctx.stroke();
      [[a, colours.A], [b, colours.B]].forEach(function (pc) {
        ctx.beginPath();
        ctx.arc(pc[0][0], pc[0][1], 2.6, 0, 2 * Math.PI);
        ctx.fillStyle = pc[1];
        ctx.fill();
      });
      centre = add(centre, add(c.a, c.b, 1), 0.5);
      count += 1;
    });
    if (run.colliding) {
      const from = count ? scaled(centre, 1 / count) : this.centre;
      const tail = this.at(from), head = this.at(add(from, run.normal, 0.25 * size / this.zoom));
      this.path(ctx, [tail, head], false);
      ctx.strokeStyle = "#111";
      ctx.lineWidth = 1.8;
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(head[0], head[1], 3, 0, 2 * Math.PI);
      ctx.fillStyle = "#111";
      ctx.fill();
    }
    if (run.broken && run.broken.contact >= 0 && run.contacts[run.broken.contact]) {
      const c = run.contacts[run.broken.contact];
      const at = this.at(add(c.a, c.b, 1).map(function (x) { return x / 2; }));
      ctx.beginPath();
      ctx.arc(at[0], at[1], 10, 0, 2 * Math.PI);
      ctx.strokeStyle = colours.broken;
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.fillStyle = colours.broken;
      ctx.font = "11px sans-serif";
      ctx.fillText(run.broken.name + " (contact " + run.broken.contact + ")", at[0] + 12, at[1] - 12);
    }
  };

  View.prototype.listen = function () {
    const self = this;
    let last = null;
    this.canvas.addEventListener("mousedown", function (e) { last = [e.clientX, e.clientY]; });
    window.addEventListener("mouseup", function () { last = null; });
    window.addEventListener("mousemove", function (e) {
      if (!last) return;
      const dx = e.clientX - last[0], dy = e.clientY - last[1];
      last = [e.clientX, e.clientY];
      // Horizontal drags turn about the view's up, vertical ones about its right.
      self.right = unit(turned(self.right, self.up, -dx * 0.01));
      const right = self.right;
      self.up = unit(turned(self.up, right, -dy * 0.01));
      self.right = unit(cross(self.up, cross(right, self.up)));
      self.draw();
    });
    this.canvas.addEventListener("wheel", function (e) {
      e.preventDefault();
      self.zoom *= Math.exp(-e.deltaY * 0.001);
      self.draw();
    }, { passive: false });
  };

  function inked(canvas) {
    const pixels = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    let count = 0;
    for (let k = 0; k < pixels.length; k += 4) if (pixels[k] < 240 || pixels[k + 1] < 240 || pixels[k + 2] < 240) count += 1;
    return count;
  }

  function show(host, runs) {
    let drawn = 0, ink = 0;
    runs.forEach(function (run) {
      const box = document.createElement("div");
      const heading = document.createElement("h3");
      heading.textContent = run.title;
      box.appendChild(heading);
      const canvas = document.createElement("canvas");
      canvas.width = size;
      canvas.height = size;
      const view = new View(run, canvas);
      Object.keys(view.views).forEach(function (name) {
        const button = document.createElement("button");
        button.textContent = name;
        button.addEventListener("click", function () { view.set(name); });
        box.appendChild(button);
      });
      box.appendChild(document.createElement("br"));
      box.appendChild(canvas);
      const legend = document.createElement("pre");
      legend.textContent = run.legend.join("\n") +
        (run.broken ? "\nFAILS " + run.broken.name + ": " + run.broken.detail : "");
      box.appendChild(legend);
      host.appendChild(box);
      view.listen();
      drawn += 1;
      ink += inked(canvas);
    });
    host.dataset.caseViews = String(runs.length);
    return [drawn, ink];
  }

  function main() {
    let drawn = 0, ink = 0;
    document.querySelectorAll("script.case-data").forEach(function (element) {
      const result = show(element.previousElementSibling, JSON.parse(element.textContent));
      drawn += result[0];
      ink += result[1];
    });
    const svgs = Array.prototype.filter.call(document.querySelectorAll("svg"), function (s) {
      return s.querySelectorAll("polygon, line, circle, rect, path").length > 0;
    });
    document.body.dataset.drawn = String(drawn);
    document.body.dataset.inked = String(ink);
    document.body.dataset.svgs = String(svgs.length);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", main);
  else main();
})();
