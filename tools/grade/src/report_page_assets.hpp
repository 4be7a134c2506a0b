#pragma once
// report.html's own style and script (the class page; a run's player is player.css/player.js),
// as string literals: the page is one file that names nothing outside its folder.

namespace aula::grade {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 16px; color: #222; }
table.sortable { border-collapse: collapse; margin: 12px 0; }
table.sortable th, table.sortable td { border: 1px solid #ccc; padding: 4px 8px; text-align: right; }
table.sortable th { background: #eef2f8; cursor: pointer; user-select: none; }
table.sortable th:after { content: ' \2195'; color: #999; }
.table-box { overflow-x: auto; max-width: 100%; }
td.name, td.why { text-align: left; }
td.why { color: #b71c1c; min-width: 18em; max-width: 40em; overflow-wrap: anywhere; }
td.why details summary { cursor: pointer; }
td.why details:not([open]) summary::after { content: '\2026 (more)'; }
@media (max-width: 600px) { td.why { min-width: 12em; } }
.runs { display: flex; flex-wrap: wrap; gap: 10px; }
.run { border: 1px solid #ccc; padding: 6px; width: 320px; max-width: 100%; box-sizing: border-box; font-size: 13px; overflow-wrap: anywhere; }
.run .failed, .run ul.diagnostics { color: #b71c1c; }
.run ul.diagnostics { margin: 4px 0; padding-left: 18px; }
h2 { border-bottom: 1px solid #ddd; padding-bottom: 4px; }
.worlds { display: flex; flex-wrap: wrap; gap: 16px; }
.worlds svg { max-width: 100%; height: auto; }
.filter { margin: 8px 0; }
.run button { margin: 4px 0; }
.run.open { width: 100%; }
.run .watch { margin-top: 6px; }
.run iframe.player-frame { width: 100%; height: 80vh; border: 1px solid #ccc; box-sizing: border-box; }
.run img.still { max-width: 100%; height: auto; display: block; }
tr.flagged td.name { color: #b71c1c; }
ul.flagged-runs { overflow-wrap: anywhere; }
details.pair pre { overflow-x: auto; max-width: 100%; }
)";

// Click a header to sort by it (numbers as numbers); again to reverse.
constexpr const char* kSortScript = R"(
document.querySelectorAll('table.sortable th').forEach((th, column) => {
  th.addEventListener('click', () => {
    const body = th.closest('table').tBodies[0];
    const rows = Array.from(body.rows);
    const up = th.dataset.order !== 'up';
    th.dataset.order = up ? 'up' : 'down';
    const key = r => { const t = r.cells[column].innerText; const n = parseFloat(t); return isNaN(n) ? t : n; };
    rows.sort((a, b) => { const x = key(a), y = key(b); return (x < y ? -1 : x > y ? 1 : 0) * (up ? 1 : -1); });
    rows.forEach(r => body.appendChild(r));
  });
});
// Filter the students: by name, and the flagged ones only.
function filterStudents() {
  const text = document.getElementById('filter-text').value.toLowerCase();
  const flagged = document.getElementById('filter-flagged').checked;
  document.querySelectorAll('table.students tbody tr').forEach(r => {
    const show = r.dataset.student.toLowerCase().includes(text) && (!flagged || r.classList.contains('flagged'));
    r.style.display = show ? '' : 'none';
  });
  document.querySelectorAll('section.student').forEach(s => {
    const show = s.dataset.student.toLowerCase().includes(text) && (!flagged || s.dataset.flagged === 'yes');
    s.style.display = show ? '' : 'none';
  });
}
document.getElementById('filter-text').addEventListener('input', filterStudents);
document.getElementById('filter-flagged').addEventListener('change', filterStudents);
// A run's player: its own page (runs/<student>/<world>-seed<k>.html, beside this one) in a frame,
// made when it is opened; `hash` (t=SECONDS, layers=...) is passed to its page (a new #t= on an
// open page moves its player).
function watch(id, hash) {
  const card = document.getElementById('card-' + id);
  const button = card && card.querySelector('button.open-run');
  if (!button) return;
  card.classList.add('open');
  let frame = card.querySelector('iframe');
  if (!frame) {
    frame = document.createElement('iframe');
    frame.className = 'player-frame';
    frame.title = 'the run\'s player: ' + id;
    card.querySelector('.watch').appendChild(frame);
  }
  frame.src = button.dataset.page + (hash ? '#' + hash : '');
}
document.querySelectorAll('button.open-run').forEach(b => b.addEventListener('click', () => watch(b.dataset.run)));
// A run's page in a frame says how tall it is: the frame takes that height (no scrollbar in a scrollbar).
window.addEventListener('message', e => {
  if (!e.data || typeof e.data.aulaPageHeight !== 'number') return;
  document.querySelectorAll('iframe.player-frame').forEach(f => {
    if (f.contentWindow === e.source) f.style.height = Math.min(4000, Math.ceil(e.data.aulaPageHeight) + 4) + 'px';
  });
});
// #run=ID&t=SECONDS&layers=...: that run's player, paused there (on load, and whenever the address
// changes); all but run= is the run's page's own.
function followHash() {
  const run = /(?:^#|&)run=([^&]+)/.exec(location.hash);
  const rest = location.hash.replace(/^#/, '').split('&').filter(part => part && !part.startsWith('run=')).join('&');
  if (run) watch(decodeURIComponent(run[1]), rest);
}
window.addEventListener('hashchange', followHash);
followHash();
// When the page had loaded, for the bench (docs/performance.md); then the still pictures, each
// when its card comes near the screen (not before: 450 pictures would hold the page's load).
window.addEventListener('load', () => {
  document.body.dataset.loadedMs = Math.round(performance.now());
  const near = new IntersectionObserver(entries => entries.forEach(e => {
    if (!e.isIntersecting) return;
    e.target.src = e.target.dataset.src;
    near.unobserve(e.target);
  }), {rootMargin: '800px'});
  document.querySelectorAll('img.still[data-src]').forEach(img => near.observe(img));
});
)";

}  // namespace aula::grade
