  // Autopark in aula grade's player (tools/grade/src/player.js): the parked cars, the curb and the
  // ideal pose the referee measures against; at the end, the referee's own words for how the car stood.
  DRAWINGS.autopark = {
    scene(p, ctx) {
      const st = p.trace.state, robot = p.trace.robot;
      ctx.fillStyle = '#9aa7b8';
      for (const b of [st.rear_car, st.front_car]) { p.box(ctx, b[0], b[1], b[2], b[3], b[4]); ctx.fill(); }
      const [, cy] = p.px(0, st.curb_y_m);
      ctx.strokeStyle = '#555'; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(0, cy); ctx.lineTo(p.canvas.width, cy); ctx.stroke();
      ctx.strokeStyle = '#2e7d32'; ctx.setLineDash([6, 4]);
      p.box(ctx, st.ideal_pose[0], st.ideal_pose[1], st.ideal_pose[2], robot.length_m, robot.width_m);
      ctx.stroke(); ctx.setLineDash([]);
    },
    // The breakdown's rows, as the referee wrote them.
    overlay(p, ctx, t) {
      if (t < p.end - 1e-9) return;
      const rows = Object.fromEntries(p.trace.breakdown.map(row => [row.term, row.measure]));
      caption(ctx, [rows.parked || rows.time, 'distances: ' + rows.distances].filter(Boolean), p.canvas.width);
    },
  };
