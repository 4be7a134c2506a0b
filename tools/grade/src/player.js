'use strict';
const AulaPlayer = (() => {
  const DIGITS = '0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz';
  const errors = [];
  window.addEventListener('error', e => errors.push(String(e.message)));
  window.addEventListener('unhandledrejection', e => errors.push(String(e.reason)));
  document.addEventListener('securitypolicyviolation', e => errors.push('blocked ' + e.blockedURI));
  const COLOURS = {bump: '#d32f2f', contact: '#d32f2f', stuck: '#ef6c00', mark: '#2e7d32', measure: '#2e7d32',
                   start: '#1565c0', end: '#222', arrival: '#2e7d32', parked: '#2e7d32', fault: '#6a1b9a',
                   aborted: '#6a1b9a', tampering: '#6a1b9a', lost: '#6a1b9a'};

  async function inflate(b64) {
    const bin = Uint8Array.from(atob(b64), c => c.charCodeAt(0));
    const stream = new Blob([bin]).stream().pipeThrough(new DecompressionStream('deflate'));
    return JSON.parse(await new Response(stream).text());
  }
  function undelta(a) {
    const out = new Array(a.length);
    let v = 0;
    for (let i = 0; i < a.length; ++i) { v += a[i]; out[i] = v; }
    return out;
  }
  // The vacuum's cleaned cells: per sample, a flat [col, row, col, row, ...] (cleaned_cells_trace.hpp).
  function decodeCells(text) {
    const samples = [[]];
    const d = c => DIGITS.indexOf(c);
    let col = 0, row = 0;
    for (let i = 0; i < text.length;) {
      const c = text[i];
      if (c === ' ') { samples.push([]); ++i; continue; }
      if (c === '~') {
        col = (d(text[i + 1]) * 62 + d(text[i + 2])) * 62 + d(text[i + 3]);
        row = (d(text[i + 4]) * 62 + d(text[i + 5])) * 62 + d(text[i + 6]);
        i += 7;
      } else {
        col += d(c) - 31;
        row += d(text[i + 1]) - 31;
        i += 2;
      }
      samples[samples.length - 1].push(col, row);
    }
    return samples;
  }
  function mapCanvas(map) {
    const [w, h] = map.size_px;
    const c = document.createElement('canvas');
    c.width = w; c.height = h;
    const ctx = c.getContext('2d');
    const img = ctx.createImageData(w, h);
    const px = img.data;
    let i = 0, free = true;
    for (const run of map.rle) {
      const v = free ? 255 : 70;
      for (let k = 0; k < run; ++k, ++i) { px[4 * i] = px[4 * i + 1] = px[4 * i + 2] = v; px[4 * i + 3] = 255; }
      free = !free;
    }
    ctx.putImageData(img, 0, 0);
    return c;
  }
  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  const fmt = (v, d) => Number(v).toFixed(d);

  class Player {
    constructor(root, data) {
      this.root = root;
      this.report = data.report;
      const t = this.trace = data.trace;
      this.period = t.samples.period_s;
      this.n = t.samples.count;
      this.xs = undelta(t.samples.x_mm);
      this.ys = undelta(t.samples.y_mm);
      this.yaws = undelta(t.samples.yaw_mrad);
      this.events = t.events.slice().sort((a, b) => a.t_s - b.t_s);
      this.end = Math.max(0, (this.n - 1) * this.period, ...this.events.map(e => e.t_s + Math.max(0, e.duration_s || 0)));
      const m = t.map;
      this.res = m.resolution_m; this.ox = m.origin_m[0]; this.oy = m.origin_m[1];
      this.map = mapCanvas(m);
      this.scale = Math.min(640 / m.size_px[0], 520 / m.size_px[1]);
      if (t.exercise === 'vacuum') {
        this.cells = decodeCells(t.state.cells);
        this.coverage = undelta(t.state.coverage_cp);
        this.cellLayer = el('canvas');
        this.cellLayer.width = m.size_px[0]; this.cellLayer.height = m.size_px[1];
        this.cellsPainted = 0;
      }
      this.time = 0; this.playing = false; this.speed = 10;
      this.build();
      this.seek(0);
    }

    build() {
      const r = this.root;
      r.classList.add('player');
      r.innerHTML = '';
      const view = el('div', {class: 'view'});
      const left = el('div');
      this.canvas = el('canvas', {width: Math.round(this.map.width * this.scale), height: Math.round(this.map.height * this.scale)});
      left.appendChild(this.canvas);
      const controls = el('div', {class: 'controls'});
      this.play = el('button', {type: 'button', class: 'play'}, 'Play');
      this.play.addEventListener('click', () => this.playing ? this.pause() : this.start());
      this.speedSelect = el('select', {class: 'speed', title: 'speed'});
      for (const s of [1, 2, 5, 10, 20, 50, 100]) {
        const o = el('option', {value: s}, s + 'x');
        if (s === this.speed) o.selected = true;
        this.speedSelect.appendChild(o);
      }
      this.speedSelect.addEventListener('change', () => { this.speed = Number(this.speedSelect.value); });
      this.slider = el('input', {type: 'range', min: 0, max: this.end, step: this.period, value: 0, class: 'time'});
      this.slider.addEventListener('input', () => { this.pause(); this.seek(Number(this.slider.value)); });
      this.clock = el('span', {class: 'clock'});
      controls.append(this.play, this.speedSelect, this.slider, this.clock);
      left.appendChild(controls);
      this.timeline = el('div', {class: 'timeline', title: 'the referee\'s events: click one to jump there'});
      for (const e of this.events) {
        const tick = el('span', {class: 'tick', title: fmt(e.t_s, 1) + ' s: ' + e.text + (e.effect ? ' (' + e.effect + ')' : '')});
        tick.style.left = (100 * e.t_s / Math.max(this.end, 1e-9)) + '%';
        tick.style.background = COLOURS[e.kind] || '#555';
        tick.addEventListener('click', () => { this.pause(); this.seek(e.t_s); });
        this.timeline.appendChild(tick);
      }
      this.cursor = el('div', {class: 'cursor'});
      this.timeline.appendChild(this.cursor);
      left.appendChild(this.timeline);
      this.status = el('div', {class: 'status'});
      left.appendChild(this.status);
      const side = el('div', {class: 'side'});
      side.appendChild(el('h3', {}, 'Mark ' + fmt(this.report.mark, 2) + ' / 10'));
      side.appendChild(this.breakdownTable());
      side.appendChild(el('h3', {}, 'What the referee saw (' + this.events.length + ' events)'));
      const list = el('table', {class: 'events'});
      list.appendChild(el('tr')).append(el('th', {}, 's'), el('th', {}, 'what'), el('th', {}, 'effect on the mark'));
      this.rows = this.events.map(e => {
        const row = el('tr', {class: 'event'});
        row.append(el('td', {class: 'n'}, fmt(e.t_s, 1)), el('td', {}, e.text), el('td', {}, e.effect));
        row.addEventListener('click', () => { this.pause(); this.seek(e.t_s); });
        list.appendChild(row);
        return row;
      });
      side.appendChild(list);
      view.append(left, side);
      r.appendChild(view);
    }

    breakdownTable() {
      const table = el('table', {class: 'breakdown'});
      table.appendChild(el('tr')).append(el('th', {}, 'term'), el('th', {}, 'measure'), el('th', {}, 'points'),
                                         el('th', {}, 'of'), el('th', {}, 'missed'));
      let sum = 0, most = 0;
      for (const term of this.trace.breakdown) {
        sum += term.points; most += term.of;
        const missed = term.of - term.points;
        const row = el('tr');
        row.append(el('td', {}, term.term), el('td', {}, term.measure), el('td', {class: 'n'}, fmt(term.points, 2)),
                   el('td', {class: 'n'}, fmt(term.of, 2)), el('td', {class: 'n' + (missed > 1e-9 ? ' missed' : '')}, fmt(missed, 2)));
        table.appendChild(row);
      }
      const total = el('tr');
      total.append(el('th', {}, 'mark'), el('th', {}, 'the report\'s mark: ' + fmt(this.report.mark, 2)),
                   el('th', {class: 'n'}, fmt(sum, 2)), el('th', {class: 'n'}, fmt(most, 2)), el('th', {class: 'n'}, fmt(most - sum, 2)));
      table.appendChild(total);
      this.breakdownSum = sum;
      return table;
    }

    start() {
      if (this.time >= this.end) this.seek(0);
      this.playing = true;
      this.play.textContent = 'Pause';
      let last = null;
      const step = now => {
        if (!this.playing) return;
        if (last !== null) this.seek(this.time + (now - last) / 1000 * this.speed);
        last = now;
        if (this.time >= this.end) { this.pause(); return; }
        requestAnimationFrame(step);
      };
      requestAnimationFrame(step);
    }
    pause() { this.playing = false; this.play.textContent = 'Play'; }

    // The pose at `t`: linear between the two samples around it (the heading the short way).
    poseAt(t) {
      const f = Math.min(Math.max(t / this.period, 0), this.n - 1);
      const i = Math.floor(f), j = Math.min(i + 1, this.n - 1), a = f - i;
      let dyaw = this.yaws[j] - this.yaws[i];
      dyaw -= 2000 * Math.PI * Math.round(dyaw / (2000 * Math.PI));
      return {x: this.xs[i] + a * (this.xs[j] - this.xs[i]), y: this.ys[i] + a * (this.ys[j] - this.ys[i]),
              yaw: this.yaws[i] + a * dyaw, sample: i};
    }
    px(x_m, y_m) { return [(x_m - this.ox) / this.res * this.scale, (this.oy - y_m) / this.res * this.scale]; }
    len(m) { return m / this.res * this.scale; }

    seek(t) {
      this.time = Math.min(Math.max(t, 0), this.end);
      this.slider.value = this.time;
      this.draw();
    }

    paintCells(sample) {
      const ctx = this.cellLayer.getContext('2d');
      if (sample < this.cellsPainted) { ctx.clearRect(0, 0, this.cellLayer.width, this.cellLayer.height); this.cellsPainted = 0; }
      const k = this.trace.state.cell_px;
      ctx.fillStyle = 'rgb(90,175,240)';
      for (; this.cellsPainted <= sample && this.cellsPainted < this.cells.length; ++this.cellsPainted) {
        const c = this.cells[this.cellsPainted];
        for (let i = 0; i < c.length; i += 2) ctx.fillRect(c[i] * k, c[i + 1] * k, k, k);
      }
    }

    box(ctx, x, y, yaw, length, width) {
      const c = Math.cos(yaw), s = Math.sin(yaw);
      ctx.beginPath();
      [[-1, -1], [1, -1], [1, 1], [-1, 1]].forEach(([l, w], i) => {
        const [u, v] = this.px(x + c * l * length / 2 - s * w * width / 2, y + s * l * length / 2 + c * w * width / 2);
        i ? ctx.lineTo(u, v) : ctx.moveTo(u, v);
      });
      ctx.closePath();
    }

    draw() {
      const ctx = this.canvas.getContext('2d');
      const t = this.time, tr = this.trace, st = tr.state;
      const pose = this.poseAt(t);
      ctx.imageSmoothingEnabled = false;
      ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
      ctx.drawImage(this.map, 0, 0, this.canvas.width, this.canvas.height);
      if (this.cells) {
        this.paintCells(Math.floor(t / this.period + 1e-9));
        ctx.globalAlpha = 0.85;
        ctx.drawImage(this.cellLayer, 0, 0, this.canvas.width, this.canvas.height);
        ctx.globalAlpha = 1;
      }
      if (tr.exercise === 'teletaxi') {
        const [dx, dy] = this.px(st.destination_m[0], st.destination_m[1]);
        ctx.strokeStyle = '#d32f2f'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.arc(dx, dy, Math.max(3, this.len(st.arrival_radius_m)), 0, 2 * Math.PI); ctx.stroke();
        ctx.fillStyle = '#d32f2f'; ctx.beginPath(); ctx.arc(dx, dy, 4, 0, 2 * Math.PI); ctx.fill();
        const [sx, sy] = this.px(st.start_m[0], st.start_m[1]);
        ctx.fillStyle = '#1565c0'; ctx.beginPath(); ctx.arc(sx, sy, 4, 0, 2 * Math.PI); ctx.fill();
      }
      if (tr.exercise === 'autopark') {
        ctx.fillStyle = '#9aa7b8';
        for (const b of [st.rear_car, st.front_car]) { this.box(ctx, b[0], b[1], b[2], b[3], b[4]); ctx.fill(); }
        const [, cy] = this.px(0, st.curb_y_m);
        ctx.strokeStyle = '#555'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(0, cy); ctx.lineTo(this.canvas.width, cy); ctx.stroke();
        ctx.strokeStyle = '#2e7d32'; ctx.setLineDash([6, 4]);
        this.box(ctx, st.ideal_pose[0], st.ideal_pose[1], st.ideal_pose[2], tr.robot.length_m, tr.robot.width_m);
        ctx.stroke(); ctx.setLineDash([]);
      }
      // The trail to now.
      ctx.strokeStyle = '#ef6c00'; ctx.lineWidth = 2;
      ctx.beginPath();
      for (let i = 0; i <= pose.sample; ++i) {
        const [u, v] = this.px(this.xs[i] / 1000, this.ys[i] / 1000);
        i ? ctx.lineTo(u, v) : ctx.moveTo(u, v);
      }
      if (this.n > 0) ctx.lineTo(...this.px(pose.x / 1000, pose.y / 1000));
      ctx.stroke();
      // The events so far, where they happened.
      let current = -1;
      this.events.forEach((e, i) => {
        const past = e.t_s <= t + 1e-9;
        if (past) current = i;
        this.rows[i].className = 'event' + (past ? '' : ' future');
        if (!past || e.x_mm === undefined) return;
        const [u, v] = this.px(e.x_mm / 1000, e.y_mm / 1000);
        ctx.strokeStyle = COLOURS[e.kind] || '#555'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(u - 5, v - 5); ctx.lineTo(u + 5, v + 5); ctx.moveTo(u + 5, v - 5); ctx.lineTo(u - 5, v + 5); ctx.stroke();
      });
      if (current >= 0) this.rows[current].className = 'event now';
      // The robot.
      if (this.n > 0) {
        const x = pose.x / 1000, y = pose.y / 1000, yaw = pose.yaw / 1000;
        const [u, v] = this.px(x, y);
        ctx.fillStyle = 'rgba(255,143,0,0.85)'; ctx.strokeStyle = '#000'; ctx.lineWidth = 2;
        let reach;
        if (tr.robot.shape === 'disc') {
          reach = tr.robot.radius_m;
          ctx.beginPath(); ctx.arc(u, v, Math.max(3, this.len(reach)), 0, 2 * Math.PI);
        } else {
          reach = tr.robot.length_m / 2;
          this.box(ctx, x, y, yaw, tr.robot.length_m, tr.robot.width_m);
        }
        ctx.fill(); ctx.stroke();
        const [hx, hy] = this.px(x + Math.cos(yaw) * reach, y + Math.sin(yaw) * reach);
        ctx.beginPath(); ctx.moveTo(u, v); ctx.lineTo(hx, hy); ctx.stroke();
      }
      if (tr.exercise === 'autopark' && t >= this.end - 1e-9) {
        ctx.fillStyle = '#000'; ctx.font = '13px sans-serif';
        ctx.fillText('gaps: front ' + fmt(st.gaps_m[0], 2) + ' m (' + st.gap_scores[0] + '), rear ' + fmt(st.gaps_m[1], 2) + ' m (' +
                     st.gap_scores[1] + '), curb ' + fmt(st.gaps_m[2], 2) + ' m (' + st.gap_scores[2] + ')', 8, 18);
      }
      let text = fmt(t, 1) + ' / ' + fmt(this.end, 1) + ' s';
      if (this.coverage) text += ', coverage ' + fmt(this.coverage[Math.min(pose.sample, this.coverage.length - 1)] / 100, 2) + ' %';
      this.clock.textContent = text;
      this.cursor.style.left = (100 * t / Math.max(this.end, 1e-9)) + '%';
      const s = this.status;
      s.textContent = current >= 0 ? 'last event: ' + fmt(this.events[current].t_s, 1) + ' s, ' + this.events[current].text : 'no event yet';
      s.dataset.tS = fmt(t, 3);
      s.dataset.robotXMm = Math.round(pose.x);
      s.dataset.robotYMm = Math.round(pose.y);
      s.dataset.robotYawMrad = Math.round(pose.yaw);
      s.dataset.breakdownSum = fmt(this.breakdownSum, 4);
      s.dataset.mark = fmt(this.report.mark, 4);
      s.dataset.errors = errors.length;
      s.dataset.errorText = errors.join(' | ');
      s.dataset.resources = performance.getEntriesByType('resource').length;
    }
  }

  // The run's player, built into `container` the first time it is opened.
  async function openRun(id, container) {
    if (container.dataset.built) return container.player;
    container.dataset.built = 'yes';
    const started = performance.now();
    const block = document.getElementById(id);
    const data = await inflate(block.textContent.trim());
    container.player = new Player(container, data);
    container.dataset.openMs = Math.round(performance.now() - started);  // decoded and drawn
    return container.player;
  }
  // `#t=SECONDS`: the player paused there.
  function hashTime() {
    const m = /t=([0-9.]+)/.exec(location.hash);
    return m ? Number(m[1]) : null;
  }
  // When the page had loaded, for the bench (docs/performance.md).
  window.addEventListener('load', () => { document.body.dataset.loadedMs = Math.round(performance.now()); });
  return {openRun, hashTime, errors};
})();
