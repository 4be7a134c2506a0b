  // The vacuum cleaner in aula grade's player (tools/grade/src/player.js): the cells it cleaned,
  // painted sample by sample, and the referee's coverage after the time.
  // The cleaned cells: per sample, a flat [col, row, col, row, ...] (cleaned_cells_trace.hpp).
  function decodeVacuumCells(text) {
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
  DRAWINGS.vacuum = {
    init(p) {
      const st = p.trace.state, size = p.trace.map.size_px;
      p.cells = decodeVacuumCells(st.cells);
      p.coverage = undelta(st.coverage_cp);
      p.cellLayer = el('canvas');
      p.cellLayer.width = size[0]; p.cellLayer.height = size[1];
      p.cellsPainted = 0;
    },
    // The cells cleaned up to `sample`, painted once each (from the start again when seeking back).
    paintCells(p, sample) {
      const ctx = p.cellLayer.getContext('2d');
      if (sample < p.cellsPainted) { ctx.clearRect(0, 0, p.cellLayer.width, p.cellLayer.height); p.cellsPainted = 0; }
      const k = p.trace.state.cell_px;
      ctx.fillStyle = 'rgb(90,175,240)';
      for (; p.cellsPainted <= sample && p.cellsPainted < p.cells.length; ++p.cellsPainted) {
        const c = p.cells[p.cellsPainted];
        for (let i = 0; i < c.length; i += 2) ctx.fillRect(c[i] * k, c[i + 1] * k, k, k);
      }
    },
    scene(p, ctx, t) {
      this.paintCells(p, Math.floor(t / p.period + 1e-9));
      ctx.globalAlpha = 0.85;
      ctx.drawImage(p.cellLayer, 0, 0, p.canvas.width, p.canvas.height);
      ctx.globalAlpha = 1;
    },
    // At the last pose graded, the referee's own figure (the report's); before it, the samples'.
    clock(p, pose, t) {
      const cp = pose.final || t >= p.end - 1e-9 ? p.trace.state.coverage_percent
                                                 : p.coverage[Math.min(pose.sample, p.coverage.length - 1)] / 100;
      return ', coverage ' + fmt(cp, 2) + ' %';
    },
  };
