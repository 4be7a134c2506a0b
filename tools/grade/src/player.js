'use strict';
// The run player (run_page.hpp): a run as its referee graded it, from the referee's trace
// (aula/referee/run_trace.hpp). Every number it shows is the referee's: the breakdown's rows
// (terms added, rules' factors applied, top to bottom), the events' texts and effects, the
// exercise's state. It computes nothing of the rubric; when the rows do not make the report's
// mark it says so.
const AulaPlayer = (() => {
  const DIGITS = '0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz';
  const errors = [];
  window.addEventListener('error', e => errors.push(String(e.message)));
  window.addEventListener('unhandledrejection', e => errors.push(String(e.reason)));
  document.addEventListener('securitypolicyviolation', e => errors.push('blocked ' + e.blockedURI));
  const COLOURS = {bump: '#d32f2f', contact: '#d32f2f', stuck: '#ef6c00', mark: '#2e7d32', measure: '#2e7d32',
                   start: '#1565c0', end: '#222', arrival: '#2e7d32', parked: '#2e7d32', fault: '#6a1b9a',
                   aborted: '#6a1b9a', tampering: '#6a1b9a', lost: '#6a1b9a', 'non-finite': '#6a1b9a'};
  const STEP_S = 1, BIG_STEP_S = 10;  // the arrow keys' steps (Shift: the big one)
  const MIN_ROBOT_PX = 14;  // the robot's drawn length at the least, at every zoom
  const ZOOMS = [1, 2, 4, 8];
  // Each exercise's drawing, by name: {init(player), scene(player, ctx, t) under the trail, overlay(player,
  // ctx, t) over the view, clock(player, pose, t) text after the time}. Filled by the exercises' player.js
  // files, inlined here at build time (aula_exercise PLAYER; tools/grade/CMakeLists.txt).
  const DRAWINGS = {};

  async function inflate(b64) {
    const bin = Uint8Array.from(atob(b64.trim()), c => c.charCodeAt(0));
    const stream = new Blob([bin]).stream().pipeThrough(new DecompressionStream('deflate'));
    return JSON.parse(await new Response(stream).text());
  }
  function undelta(a) {
    const out = new Array(a.length);
    let v = 0;
    for (let i = 0; i < a.length; ++i) { v += a[i]; out[i] = v; }
    return out;
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
  // The breakdown's rows read top to bottom: a term adds its points, a rule multiplies the total so far.
  function foldBreakdown(rows) {
    let total = 0, most = 0;
    for (const row of rows) {
      if (row.factor !== undefined) { total *= row.factor; continue; }
      total += row.points; most += row.of;
    }
    return {total, most};
  }
  // `lines` in white on a dark box at the canvas's top left, each wrapped to the canvas's width.
  function caption(ctx, lines, width) {
    ctx.font = '13px sans-serif';
    const wrapped = [];
    for (const line of lines) {
      let current = '';
      for (const word of line.split(' ')) {
        const next = current ? current + ' ' + word : word;
        if (current && ctx.measureText(next).width > width - 20) { wrapped.push(current); current = word; } else current = next;
      }
      if (current) wrapped.push(current);
    }
    const w = Math.min(width - 8, Math.max(...wrapped.map(l => ctx.measureText(l).width)) + 12);
    ctx.fillStyle = 'rgba(20, 24, 32, 0.82)';
    ctx.fillRect(4, 4, w, 8 + 17 * wrapped.length);
    ctx.fillStyle = '#fff';
    wrapped.forEach((l, i) => ctx.fillText(l, 10, 20 + 17 * i));
  }

/* @AULA_EXERCISE_PLAYERS@ */

/* @AULA_PLAYER_LAYERS@ */

  let active = null;  // the player the keys drive: the last one opened or touched

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
      // The exercise's own drawing (its player.js, declared by its aula_exercise): none draws nothing more.
      this.drawing = DRAWINGS[t.exercise] || {};
      if (this.drawing.init) this.drawing.init(this);
      // The trace's layers this run has (player_layers.js), each on but the laser's rays until switched.
      this.layers = LAYERS.filter(l => l.has(t));
      for (const l of this.layers) l.init(this);
      this.shown = {laser: false, belief: true, plan: true, console: true};
      this.time = 0; this.playing = false; this.speed = 10; this.current = -2;
      this.zoom = 1; this.follow = false;
      this.build();
      this.seek(0);
      active = this;
    }

    build() {
      const r = this.root;
      r.classList.add('player');
      r.innerHTML = '';
      r.addEventListener('pointerdown', () => { active = this; });
      r.addEventListener('focusin', () => { active = this; });
      const view = el('div', {class: 'view'});
      const stage = el('div', {class: 'stage'});
      this.statusId = 'status-' + Math.random().toString(36).slice(2);
      this.canvas = el('canvas', {width: Math.round(this.map.width * this.scale), height: Math.round(this.map.height * this.scale),
                                  role: 'img', 'aria-label': 'the run on its map: the robot, its trail and the events so far',
                                  'aria-describedby': this.statusId});
      this.canvas.style.maxWidth = this.canvas.width + 'px';
      stage.appendChild(this.canvas);
      const controls = el('div', {class: 'controls'});
      this.play = el('button', {type: 'button', class: 'play', 'aria-keyshortcuts': 'Space'}, 'Play');
      this.play.addEventListener('click', () => this.toggle());
      this.speedSelect = el('select', {class: 'speed', 'aria-label': 'speed'});
      for (const s of [1, 2, 5, 10, 20, 50, 100]) {
        const o = el('option', {value: s}, s + 'x');
        if (s === this.speed) o.selected = true;
        this.speedSelect.appendChild(o);
      }
      this.speedSelect.addEventListener('change', () => { this.speed = Number(this.speedSelect.value); });
      this.zoomSelect = el('select', {class: 'zoom', 'aria-label': 'zoom', 'aria-keyshortcuts': '+ -'});
      for (const z of ZOOMS) this.zoomSelect.appendChild(el('option', {value: z}, 'zoom ' + z + 'x'));
      this.zoomSelect.addEventListener('change', () => { this.zoom = Number(this.zoomSelect.value); this.draw(); });
      const followLabel = el('label', {class: 'follow'});
      this.followBox = el('input', {type: 'checkbox', 'aria-keyshortcuts': 'F'});
      this.followBox.addEventListener('change', () => { this.follow = this.followBox.checked; this.draw(); });
      followLabel.append(this.followBox, ' follow the robot');
      this.slider = el('input', {type: 'range', min: 0, max: this.end, step: 'any', value: 0, class: 'time',
                                 'aria-label': 'sim time, s'});
      this.slider.addEventListener('input', () => { this.pause(); this.seek(Number(this.slider.value)); });
      this.clock = el('span', {class: 'clock'});
      const prev = el('button', {type: 'button', class: 'prev', 'aria-keyshortcuts': 'P', title: 'the previous event (P)'}, '\u25C0 event');
      prev.addEventListener('click', () => this.jumpEvent(-1));
      const next = el('button', {type: 'button', class: 'next', 'aria-keyshortcuts': 'N', title: 'the next event (N)'}, 'event \u25B6');
      next.addEventListener('click', () => this.jumpEvent(1));
      controls.append(this.play, prev, next, this.speedSelect, this.zoomSelect, followLabel, this.slider, this.clock);
      stage.appendChild(controls);
      const consolePart = this.consolePart = consolePanel(this);
      this.layerBoxes = {};
      const switches = this.layers.map(l => [l.key, l.label]).concat(consolePart ? [['console', 'printed lines']] : []);
      if (switches.length) {
        const row = el('div', {class: 'layers'});
        row.appendChild(el('span', {}, 'Layers:'));
        for (const [key, label] of switches) {
          const box = el('input', {type: 'checkbox', class: 'layer-' + key});
          box.checked = this.shown[key];
          box.addEventListener('change', () => this.showLayer(key, box.checked));
          this.layerBoxes[key] = box;
          const labelled = el('label');
          labelled.append(box, ' ' + label);
          row.appendChild(labelled);
        }
        stage.appendChild(row);
      }
      this.layerNote = el('div', {class: 'layer-note'});
      stage.appendChild(this.layerNote);
      this.timeline = el('div', {class: 'timeline', 'aria-hidden': 'true', title: 'the referee\'s events: click one to jump there'});
      for (const e of this.events) {
        const tick = el('span', {class: 'tick', title: fmt(e.t_s, 1) + ' s: ' + e.text + (e.effect ? ' (' + e.effect + ')' : '')});
        tick.style.left = (100 * e.t_s / Math.max(this.end, 1e-9)) + '%';
        tick.style.background = COLOURS[e.kind] || '#555';
        tick.addEventListener('click', () => { this.pause(); this.seek(e.t_s); });
        this.timeline.appendChild(tick);
      }
      this.cursor = el('div', {class: 'cursor'});
      this.timeline.appendChild(this.cursor);
      stage.appendChild(this.timeline);
      this.status = el('div', {class: 'status', id: this.statusId});
      stage.appendChild(this.status);
      stage.appendChild(el('div', {class: 'keys'}, 'Keys: Space play/pause, \u2190 \u2192 ' + STEP_S + ' s (Shift: ' + BIG_STEP_S +
                                                   ' s), N/P the next/previous event, Home/End, + and - zoom, F follows the robot.'));
      const side = el('div', {class: 'side'});
      const markPanel = el('div', {class: 'mark-panel'});
      markPanel.appendChild(el('h3', {}, 'Mark ' + fmt(this.report.mark, 2) + ' / 10'));
      markPanel.appendChild(this.breakdownTable());
      side.appendChild(markPanel);
      side.appendChild(el('h3', {}, 'What the referee saw (' + this.events.length + ' events)'));
      this.eventBox = el('div', {class: 'events-box'});
      const list = el('table', {class: 'events'});
      list.appendChild(el('tr')).append(el('th', {}, 's'), el('th', {}, 'what'), el('th', {}, 'effect on the mark'));
      this.rows = this.events.map(e => {
        const row = el('tr', {class: 'event future', tabindex: 0});
        row.append(el('td', {class: 'n'}, fmt(e.t_s, 1)), el('td', {}, e.text), el('td', {}, e.effect));
        const go = () => { this.pause(); this.seek(e.t_s); };
        row.addEventListener('click', go);
        row.addEventListener('keydown', k => { if (k.key === 'Enter') { k.preventDefault(); go(); } });
        list.appendChild(row);
        return row;
      });
      this.eventBox.appendChild(list);
      side.appendChild(this.eventBox);
      if (consolePart) side.appendChild(consolePart);
      view.append(stage, side);
      r.appendChild(view);
    }

    breakdownTable() {
      const table = el('table', {class: 'breakdown'});
      table.appendChild(el('tr')).append(el('th', {}, 'term'), el('th', {}, 'measure'), el('th', {}, 'points'),
                                         el('th', {}, 'of'), el('th', {}, 'missed'));
      for (const term of this.trace.breakdown) {
        const row = el('tr');
        if (term.factor !== undefined) {
          row.className = 'rule';
          row.append(el('td', {}, term.term), el('td', {}, term.measure), el('td', {class: 'n', colspan: 3}, '\u00D7 ' + fmt(term.factor, 2)));
        } else {
          const missed = term.of - term.points;
          row.append(el('td', {}, term.term), el('td', {}, term.measure), el('td', {class: 'n'}, fmt(term.points, 2)),
                     el('td', {class: 'n'}, fmt(term.of, 2)), el('td', {class: 'n' + (missed > 1e-9 ? ' missed' : '')}, fmt(missed, 2)));
        }
        table.appendChild(row);
      }
      const {total, most} = foldBreakdown(this.trace.breakdown);
      const row = el('tr', {class: 'total'});
      row.append(el('th', {}, 'mark'), el('th', {}, 'the rows above, top to bottom'), el('th', {class: 'n'}, fmt(total, 2)),
                 el('th', {class: 'n'}, fmt(most, 2)), el('th', {class: 'n'}, fmt(most - total, 2)));
      table.appendChild(row);
      if (Math.abs(total - this.report.mark) > 0.005) {
        const warn = el('tr', {class: 'missed mismatch'});
        warn.appendChild(el('td', {colspan: 5}, 'These rows make ' + fmt(total, 2) + ' but the report\'s mark is ' +
                                               fmt(this.report.mark, 2) + ': the report\'s mark counts (please tell your teacher).'));
        table.appendChild(warn);
      }
      this.breakdownSum = total;
      return table;
    }

    // A layer on or off (its box, or `#layers=` in the address: showLayers with the keys to show).
    showLayer(key, on) {
      this.shown[key] = on;
      if (this.layerBoxes[key]) this.layerBoxes[key].checked = on;
      if (key === 'console' && this.consolePart) this.consolePart.hidden = !on;
      this.draw();
    }
    showLayers(keys) { for (const key of Object.keys(this.shown)) this.showLayer(key, keys.includes(key)); }

    toggle() { this.playing ? this.pause() : this.start(); }
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
    pause() { this.playing = false; this.play.textContent = 'Play'; this.status.dataset.playing = 'no'; }
    // The next (`direction` 1) or previous (-1) event's time, paused there.
    jumpEvent(direction) {
      this.pause();
      const eps = 1e-6;
      const times = this.events.map(e => e.t_s);
      const t = direction > 0 ? times.find(s => s > this.time + eps) : times.filter(s => s < this.time - eps).pop();
      if (t !== undefined) this.seek(t);
    }
    // A key for the player: true when it was one of its own.
    key(e) {
      const target = e.target, tag = target && target.tagName;
      if (tag === 'INPUT' && target.type !== 'range') return false;  // typing in a search box
      if (tag === 'TEXTAREA' || tag === 'SELECT') return false;
      const native = tag === 'BUTTON';  // Space clicks a focused button (on the slider it plays)
      switch (e.key) {
        case ' ': if (native) return false; this.toggle(); return true;
        // The arrows step 1 s (Shift 10 s) whatever has the focus: on the slider too, whose own step
        // would be 1 % of the run (9 s of a vacuum run).
        case 'ArrowRight': case 'ArrowLeft':
          this.pause();
          this.seek(this.time + (e.key === 'ArrowRight' ? 1 : -1) * (e.shiftKey ? BIG_STEP_S : STEP_S));
          return true;
        case 'Home': this.pause(); this.seek(0); return true;
        case 'End': this.pause(); this.seek(this.end); return true;
        case 'n': case 'N': this.jumpEvent(1); return true;
        case 'p': case 'P': this.jumpEvent(-1); return true;
        case '+': case '=': case '-': {
          const i = Math.max(0, Math.min(ZOOMS.length - 1, ZOOMS.indexOf(this.zoom) + (e.key === '-' ? -1 : 1)));
          this.zoom = ZOOMS[i]; this.zoomSelect.value = this.zoom; this.draw(); return true;
        }
        case 'f': case 'F': this.follow = !this.follow; this.followBox.checked = this.follow; this.draw(); return true;
      }
      return false;
    }

    // The pose at `t`: linear between the two samples around it (the heading the short way); after
    // the last sample, towards the last pose the referee graded (the trace's "final", at its time).
    poseAt(t) {
      const f = Math.min(Math.max(t / this.period, 0), this.n - 1);
      const i = Math.floor(f), j = Math.min(i + 1, this.n - 1), a = f - i;
      const last = (this.n - 1) * this.period, fin = this.trace.final;
      if (t > last && fin && fin.traced && fin.t_s > last + 1e-9) {
        const b = Math.min(1, (t - last) / (fin.t_s - last)), k = this.n - 1;
        let dyaw = fin.pose[2] * 1000 - this.yaws[k];
        dyaw -= 2000 * Math.PI * Math.round(dyaw / (2000 * Math.PI));
        return {x: this.xs[k] + b * (fin.pose[0] * 1000 - this.xs[k]), y: this.ys[k] + b * (fin.pose[1] * 1000 - this.ys[k]),
                yaw: this.yaws[k] + b * dyaw, sample: k, final: b >= 1};
      }
      let dyaw = this.yaws[j] - this.yaws[i];
      dyaw -= 2000 * Math.PI * Math.round(dyaw / (2000 * Math.PI));
      return {x: this.xs[i] + a * (this.xs[j] - this.xs[i]), y: this.ys[i] + a * (this.ys[j] - this.ys[i]),
              yaw: this.yaws[i] + a * dyaw, sample: i, final: false};
    }
    px(x_m, y_m) { return [(x_m - this.ox) / this.res * this.scale, (this.oy - y_m) / this.res * this.scale]; }
    len(m) { return m / this.res * this.scale; }

    seek(t) {
      this.time = Math.min(Math.max(t, 0), this.end);
      this.slider.value = this.time;
      this.draw();
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

    // The event rows: past, now (the last one at or before `t`), future; the list keeps "now" in view.
    markEvents(current) {
      if (current === this.current) return;
      const from = Math.max(0, Math.min(current, this.current)), to = Math.max(current, this.current);
      for (let i = from; i <= to && i < this.rows.length; ++i) {
        this.rows[i].className = 'event' + (i === current ? ' now' : i < current ? '' : ' future');
      }
      this.current = current;
      if (current >= 0) {
        const row = this.rows[current], box = this.eventBox;
        const top = row.getBoundingClientRect().top - box.getBoundingClientRect().top + box.scrollTop;
        const bottom = top + row.offsetHeight;
        if (top < box.scrollTop || bottom > box.scrollTop + box.clientHeight) box.scrollTop = Math.max(0, top - box.clientHeight / 3);
      }
    }

    draw() {
      const ctx = this.canvas.getContext('2d');
      const t = this.time, tr = this.trace;
      const pose = this.poseAt(t);
      ctx.imageSmoothingEnabled = false;
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.fillStyle = '#f4f4f4';
      ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
      // Zoomed: about the robot when following it, else about the map's centre.
      const W = this.canvas.width, H = this.canvas.height, z = this.zoom;
      const [fu, fv] = this.follow && this.n > 0 ? this.px(pose.x / 1000, pose.y / 1000) : [W / 2, H / 2];
      ctx.setTransform(z, 0, 0, z, W / 2 - z * fu, H / 2 - z * fv);
      ctx.drawImage(this.map, 0, 0, this.canvas.width, this.canvas.height);
      const shown = this.layers.filter(l => this.shown[l.key]);
      for (const l of shown) if (l.under) l.under(this, ctx, t);
      if (this.drawing.scene) this.drawing.scene(this, ctx, t);
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
      for (let i = 0; i < this.events.length; ++i) {
        const e = this.events[i];
        if (e.t_s > t + 1e-9) break;
        current = i;
        if (e.x_mm === undefined) continue;
        const [u, v] = this.px(e.x_mm / 1000, e.y_mm / 1000);
        ctx.strokeStyle = COLOURS[e.kind] || '#555'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(u - 5, v - 5); ctx.lineTo(u + 5, v + 5); ctx.moveTo(u + 5, v - 5); ctx.lineTo(u - 5, v + 5); ctx.stroke();
      }
      this.markEvents(current);
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
          // Never shorter than MIN_ROBOT_PX on the screen (a 4 m taxi in a 500 m city is 4 px).
          const grow = Math.max(1, MIN_ROBOT_PX / Math.max(this.len(tr.robot.length_m), 1e-9));
          reach = tr.robot.length_m / 2 * grow;
          this.box(ctx, x, y, yaw, tr.robot.length_m * grow, tr.robot.width_m * grow);
        }
        ctx.fill(); ctx.stroke();
        const [hx, hy] = this.px(x + Math.cos(yaw) * reach, y + Math.sin(yaw) * reach);
        ctx.beginPath(); ctx.moveTo(u, v); ctx.lineTo(hx, hy); ctx.stroke();
      }
      for (const l of shown) if (l.over) l.over(this, ctx, t);
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      this.layerNote.textContent = shown.map(l => l.note(this, t)).filter(Boolean).join('; ');
      markConsole(this, t);
      if (this.drawing.overlay) this.drawing.overlay(this, ctx, t);
      let text = fmt(t, 1) + ' / ' + fmt(this.end, 1) + ' s';
      if (this.drawing.clock) text += this.drawing.clock(this, pose, t);
      this.clock.textContent = text;
      this.cursor.style.left = (100 * t / Math.max(this.end, 1e-9)) + '%';
      const s = this.status;
      const where = this.n > 0 ? 'the robot at x ' + fmt(pose.x / 1000, 2) + ' m, y ' + fmt(pose.y / 1000, 2) + ' m, heading ' +
                                 (Math.round(pose.yaw / Math.PI * 0.18) || 0) + ' deg; ' : '';
      s.textContent = fmt(t, 1) + ' s: ' + where + (current >= 0 ? 'last event at ' + fmt(this.events[current].t_s, 1) + ' s: ' +
                                                    this.events[current].text : 'no event yet');
      s.dataset.tS = fmt(t, 3);
      s.dataset.robotXMm = Math.round(pose.x);
      s.dataset.robotYMm = Math.round(pose.y);
      s.dataset.robotYawMrad = Math.round(pose.yaw);
      s.dataset.breakdownSum = fmt(this.breakdownSum, 4);
      s.dataset.mark = fmt(this.report.mark, 4);
      s.dataset.event = current;
      s.dataset.playing = this.playing ? 'yes' : 'no';
      s.dataset.errors = errors.length;
      s.dataset.errorText = errors.join(' | ');
      // Requests for anything not a file beside the page (the class page's pictures are): none, ever.
      s.dataset.resources = performance.getEntriesByType('resource').filter(e => !e.name.startsWith('file:')).length;
    }
  }

  document.addEventListener('keydown', e => {
    if (!active || e.ctrlKey || e.metaKey || e.altKey) return;
    if (active.key(e)) e.preventDefault();
  });

  // The run's player, built into `container` the first time it is opened.
  async function openRun(id, container) {
    if (container.dataset.built) return container.player;
    container.dataset.built = 'yes';
    const started = performance.now();
    const block = document.getElementById(id);
    let data;
    try {
      // Two blocks: the report, and the trace as the referee wrote it (run_page.cpp's runDataBlock).
      const [report, trace] = await Promise.all([inflate(block.textContent), inflate(document.getElementById(id + '-trace').textContent)]);
      data = {report, trace};
    } catch (e) {
      container.textContent = 'The run\'s data could not be read (' + e + ').';
      container.classList.add('missed');
      throw e;
    }
    container.player = new Player(container, data);
    container.dataset.openMs = Math.round(performance.now() - started);  // decoded and drawn
    return container.player;
  }
  // `#t=SECONDS`, `#run=ID` and `#layers=laser,belief,plan,console` (the layers shown, the others
  // off): what the address asks for ({run: null, t: null, layers: null} when nothing).
  function hashParts() {
    const part = name => { const m = new RegExp('(?:^#|&)' + name + '=([^&]*)').exec(location.hash); return m ? decodeURIComponent(m[1]) : null; };
    const t = part('t'), layers = part('layers');
    return {t: t !== null && /^[0-9.]+$/.test(t) ? Number(t) : null, run: part('run'), layers: layers === null ? null : layers.split(',')};
  }
  // Follows the address, now and on every change: `open(run)` gives the player (a promise), which is
  // paused at `#t=` when there is one.
  function followHash(open) {
    const go = () => {
      const {run, t, layers} = hashParts();
      const opened = open(run);
      if (!opened) return;
      opened.then(p => {
        if (!p) return;
        if (layers !== null) p.showLayers(layers);
        if (t !== null) { p.pause(); p.seek(t); }
        active = p;
      }).catch(() => {});
    };
    window.addEventListener('hashchange', go);
    go();
  }
  // When the page had loaded, for the bench (docs/performance.md).
  // The loader runs this script after inflating it, often once the page has loaded.
  const loaded = () => { document.body.dataset.loadedMs = Math.round(performance.now()); };
  if (document.readyState === 'complete') loaded();
  else window.addEventListener('load', loaded);
  return {openRun, followHash, errors};
})();
