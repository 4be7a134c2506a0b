  // The trace's layers (referees/common/include/aula/referee/trace_layers.hpp), inlined into
  // player.js at build time: what the student switches on and off over the graded run. None of it
  // is graded. Each layer: {key, label, has(trace), init(player), under(player, ctx, t) drawn on the
  // map under the exercise's scene and the trail, over(player, ctx, t) drawn over the robot, note(player,
  // t) the line under the map saying what it shows}. The printed lines are a panel of
  // the side (consolePanel below), switched the same way.

  // The element of the sorted `items` whose `time(item)` is the last at or before `t`, or -1.
  function lastAtOrBefore(items, t, time) {
    let lo = 0, hi = items.length - 1, found = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (time(items[mid]) <= t + 1e-9) { found = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return found;
  }
  // A [value, run, value, run...] picture (rows from the top unless `bottom_up`) as a canvas, each
  // value's colour from `colour(value)` as [r, g, b, a].
  function runsCanvas(size, runs, bottomUp, colour) {
    const [w, h] = size;
    const c = el('canvas');
    c.width = w; c.height = h;
    const ctx = c.getContext('2d'), img = ctx.createImageData(w, h), px = img.data;
    let i = 0;
    for (let k = 0; k + 1 < runs.length; k += 2) {
      const rgba = colour(runs[k]);
      for (let n = 0; n < runs[k + 1] && i < w * h; ++n, ++i) {
        const row = Math.floor(i / w), col = i % w, at = 4 * ((bottomUp ? h - 1 - row : row) * w + col);
        px[at] = rgba[0]; px[at + 1] = rgba[1]; px[at + 2] = rgba[2]; px[at + 3] = rgba[3];
      }
    }
    ctx.putImageData(img, 0, 0);
    return c;
  }
  // A picture whose top-left corner is at world `origin_m` (its row 0 at the top), drawn on the map.
  function drawOnMap(p, ctx, canvas, grid, bottomUp) {
    const [w, h] = grid.size_px, res = grid.resolution_m;
    const top = bottomUp ? grid.origin_m[1] + h * res : grid.origin_m[1];
    const [u, v] = p.px(grid.origin_m[0], top);
    ctx.drawImage(canvas, u, v, p.len(w * res), p.len(h * res));
  }
  const LAYERS = [
    {
      key: 'laser', label: 'laser rays',
      has: tr => tr.layers && (tr.layers.lasers || []).some(l => l.scans.length > 0),
      // Ranges in steps of range_step_m (a trace from before it: "cm"), delta-encoded along the beams.
      init(p) {
        for (const l of p.trace.layers.lasers) {
          const step_m = l.range_step_m || 0.01;
          for (const s of l.scans) s.range_m = undelta(s.ranges || s.cm).map(v => v * step_m);
        }
      },
      over(p, ctx, t) {
        for (const l of p.trace.layers.lasers) {
          const k = lastAtOrBefore(l.scans, t, s => s.t_s);
          if (k < 0) continue;
          const scan = l.scans[k], pose = p.poseAt(scan.t_s);  // where the robot was when it scanned
          const x = pose.x / 1000, y = pose.y / 1000, yaw = pose.yaw / 1000, c = Math.cos(yaw), s = Math.sin(yaw);
          const mx = x + c * l.mount[0] - s * l.mount[1], my = y + s * l.mount[0] + c * l.mount[1];
          const [u0, v0] = p.px(mx, my);
          ctx.lineWidth = 1;
          scan.range_m.forEach((r, i) => {
            const a = yaw + l.mount[2] + l.min_angle_rad + i * l.increment_rad;
            const hit = r < l.max_range_m - 1e-3;
            const [u, v] = p.px(mx + r * Math.cos(a), my + r * Math.sin(a));
            ctx.strokeStyle = hit ? 'rgba(211,47,47,0.28)' : 'rgba(211,47,47,0.08)';
            ctx.beginPath(); ctx.moveTo(u0, v0); ctx.lineTo(u, v); ctx.stroke();
            if (hit) { ctx.fillStyle = '#d32f2f'; ctx.fillRect(u - 1.5, v - 1.5, 3, 3); }
          });
        }
      },
      note: (p, t) => {
        const times = p.trace.layers.lasers.map(l => { const k = lastAtOrBefore(l.scans, t, s => s.t_s); return k < 0 ? null : l.scans[k].t_s; });
        const known = times.filter(v => v !== null), period_s = p.trace.layers.lasers[0].period_s || 1;
        return known.length ? 'laser: the scan of ' + fmt(Math.max(...known), 1) + ' s (one every ' + fmt(period_s, 0) + ' s)' : '';
      },
    },
    {
      key: 'belief', label: 'its belief',
      has: tr => tr.layers && tr.layers.belief && (tr.layers.belief.t_ms.length > 0 || tr.layers.belief.maps.length > 0),
      init(p) {
        const b = p.trace.layers.belief;
        b.t = undelta(b.t_ms).map(v => v / 1000); b.x = undelta(b.x_mm); b.y = undelta(b.y_mm); b.yaw = undelta(b.yaw_mrad);
        // As its window draws it: occupied magenta, free a light tint, unknown clear.
        for (const m of b.maps) m.canvas = runsCanvas(m.size_px, m.runs, true, v => v === 2 ? [200, 0, 200, 230] : v === 0 ? [200, 0, 200, 40] : [0, 0, 0, 0]);
      },
      under(p, ctx, t) {
        const b = p.trace.layers.belief, k = lastAtOrBefore(b.maps, t, m => m.t_s);
        if (k >= 0) drawOnMap(p, ctx, b.maps[k].canvas, b.maps[k], true);
      },
      over(p, ctx, t) {
        const b = p.trace.layers.belief, k = lastAtOrBefore(b.t, t, v => v);
        if (k < 0) return;
        const x = b.x[k] / 1000, y = b.y[k] / 1000, yaw = b.yaw[k] / 1000;
        const reach = p.trace.robot.shape === 'disc' ? p.trace.robot.radius_m : p.trace.robot.length_m / 2;
        const [u, v] = p.px(x, y), [hx, hy] = p.px(x + reach * Math.cos(yaw), y + reach * Math.sin(yaw));
        ctx.strokeStyle = 'rgb(200,0,200)'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.arc(u, v, Math.max(3, p.len(reach)), 0, 2 * Math.PI); ctx.moveTo(u, v); ctx.lineTo(hx, hy); ctx.stroke();
      },
      note: (p, t) => {
        const b = p.trace.layers.belief, k = lastAtOrBefore(b.t, t, v => v), m = lastAtOrBefore(b.maps, t, v => v.t_s);
        return k < 0 ? '' : 'magenta: what it believes (its pose of ' + fmt(b.t[k], 1) + ' s' +
                            (m >= 0 ? ', its map of ' + fmt(b.maps[m].t_s, 0) + ' s' : '') + ')';
      },
    },
    {
      key: 'plan', label: 'its plan',
      has: tr => tr.layers && (tr.layers.plans || []).length > 0,
      init(p) {
        // The field's 16 levels from dark blue (near the destination) to pale yellow (far); obstacles
        // and the unreached left to the map.
        const colour = v => {
          if (v === 0 || v === 15) return [0, 0, 0, 0];
          const a = (v - 1) / 13;
          return [Math.round(21 + a * 234), Math.round(101 + a * 135), Math.round(192 - a * 62), 150];
        };
        for (const plan of p.trace.layers.plans) if (plan.field) plan.canvas = runsCanvas(plan.size_px, plan.field, false, colour);
      },
      under(p, ctx, t) {
        const plans = p.trace.layers.plans, k = lastAtOrBefore(plans, t, v => v.t_s);
        if (k < 0) return;
        const plan = plans[k];
        if (plan.canvas) drawOnMap(p, ctx, plan.canvas, plan, false);
      },
      // The path's cells over the trail: what it planned against where it drove.
      over(p, ctx, t) {
        const plans = p.trace.layers.plans, k = lastAtOrBefore(plans, t, v => v.t_s);
        if (k < 0) return;
        const plan = plans[k], res = plan.resolution_m, side = Math.max(3, p.len(res));
        ctx.fillStyle = 'rgba(27,94,32,0.85)';
        for (let i = 0; i + 1 < plan.path.length; i += 2) {
          const [u, v] = p.px(plan.origin_m[0] + (plan.path[i] + 0.5) * res, plan.origin_m[1] - (plan.path[i + 1] + 0.5) * res);
          ctx.fillRect(u - side / 2, v - side / 2, side, side);
        }
      },
      note: (p, t) => {
        const plans = p.trace.layers.plans, k = lastAtOrBefore(plans, t, v => v.t_s);
        return k < 0 ? '' : 'its plan of ' + fmt(plans[k].t_s, 1) + ' s: the field (blue near the destination) and the path (green)';
      },
    },
  ];

  // The printed lines, in the side: each with its sim time; those still to come in grey, the last
  // one printed at or before the playhead marked and kept in view.
  function consolePanel(p) {
    const c = p.trace.layers && p.trace.layers.console;
    if (!c || c.lines.length === 0) return null;
    const panel = el('div', {class: 'console-panel'});
    panel.appendChild(el('h3', {}, 'What the program printed (' + c.lines.length + ' lines)'));
    if (c.dropped_lines > 0) {
      panel.appendChild(el('div', {class: 'missed'}, c.dropped_lines + ' lines (' + c.dropped_bytes + ' bytes) printed in between ' +
                                                     'are left out: the page keeps the first and the last ' +
                                                     Math.round(c.cap_bytes / 2048) + ' KB.'));
    }
    const box = el('div', {class: 'console-box', role: 'log', 'aria-label': 'what the program printed'});
    p.consoleRows = c.lines.map(line => {
      const row = el('div', {class: 'line future'});
      row.append(el('span', {class: 'n'}, fmt(line.t_s, 2)), el('span', {class: 'text'}, line.text));
      row.addEventListener('click', () => { p.pause(); p.seek(line.t_s); });
      box.appendChild(row);
      return row;
    });
    p.consoleBox = box;
    p.consoleNow = -2;
    panel.appendChild(box);
    return panel;
  }
  function markConsole(p, t) {
    if (!p.consoleRows) return;
    const lines = p.trace.layers.console.lines, now = lastAtOrBefore(lines, t, l => l.t_s);
    if (now === p.consoleNow) return;
    p.consoleRows.forEach((row, i) => { row.className = 'line' + (i === now ? ' now' : i < now ? '' : ' future'); });
    p.consoleNow = now;
    if (now >= 0) {
      const row = p.consoleRows[now], box = p.consoleBox;
      const top = row.offsetTop;  // the box is positioned: its rows are measured from it
      if (top < box.scrollTop || top + row.offsetHeight > box.scrollTop + box.clientHeight) box.scrollTop = Math.max(0, top - box.clientHeight / 3);
    }
  }
