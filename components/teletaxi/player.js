  // TeleTaxi in aula grade's player (tools/grade/src/player.js): the start, and the destination
  // with the referee's arrival radius.
  DRAWINGS.teletaxi = {
    scene(p, ctx) {
      const st = p.trace.state;
      const [dx, dy] = p.px(st.destination_m[0], st.destination_m[1]);
      ctx.strokeStyle = '#d32f2f'; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.arc(dx, dy, Math.max(3, p.len(st.arrival_radius_m)), 0, 2 * Math.PI); ctx.stroke();
      ctx.fillStyle = '#d32f2f'; ctx.beginPath(); ctx.arc(dx, dy, 4, 0, 2 * Math.PI); ctx.fill();
      const [sx, sy] = p.px(st.start_m[0], st.start_m[1]);
      ctx.fillStyle = '#1565c0'; ctx.beginPath(); ctx.arc(sx, sy, 4, 0, 2 * Math.PI); ctx.fill();
    },
  };
