// The player's script travels deflated in the page, in its 'aula-player' block (a third of its
// size: a class's pages are most of its folder, issue 58). This unpacks it, runs it, then calls
// `start`. A browser that cannot inflate is told so where the player would be, quietly.
function aulaLoadPlayer(start) {
  const box = document.getElementById('player');
  const missing = [];
  if (typeof DecompressionStream === 'undefined') missing.push('DecompressionStream (Chrome 80, Firefox 113, Safari 16.4 or newer)');
  if (typeof Blob === 'undefined' || !Blob.prototype.stream) missing.push('Blob.stream');
  if (missing.length) {
    box.textContent = 'This browser cannot play the run: it lacks ' + missing.join(', ') + '. Open the page in a newer browser; ' +
                      'the report\'s numbers are on this page, the referee\'s picture of the end beside it.';
    box.classList.add('missed');
    return;
  }
  const bin = Uint8Array.from(atob(document.getElementById('aula-player').textContent.trim()), c => c.charCodeAt(0));
  new Response(new Blob([bin]).stream().pipeThrough(new DecompressionStream('deflate'))).text().then(text => {
    const script = document.createElement('script');
    script.textContent = text;
    document.body.appendChild(script);
    start();
  });
}
