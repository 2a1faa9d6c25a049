// Loaded only by report_test.sh's copy of the report page (the page itself has no scripts):
// once every video has its metadata (or failed), writes one line per image and video into
// <pre id="results"> for the test to read from chromium's --dump-dom.
function report() {
  var lines = [];
  for (var img of document.images) {
    var ok = img.complete && img.naturalWidth > 0;
    lines.push('IMG ' + img.getAttribute('src') + ' ' + (ok ? 'ok' : 'FAIL') + ' ' +
               img.naturalWidth + 'x' + img.naturalHeight);
  }
  for (var v of document.querySelectorAll('video')) {
    lines.push('VIDEO ' + v.getAttribute('src') + ' ' + v.readyState + ' ' + v.duration + ' ' +
               v.videoWidth + 'x' + v.videoHeight + ' ' +
               (v.error ? 'error' + v.error.code : 'noerror'));
  }
  var pre = document.createElement('pre');
  pre.id = 'results';
  pre.textContent = '\n' + lines.join('\n') + '\n';
  document.body.appendChild(pre);
}
var tries = 0;
function poll() {
  var pending = Array.from(document.querySelectorAll('video'))
                    .some(function(v) { return v.readyState < 1 && !v.error; });
  if (pending && ++tries < 200) {
    setTimeout(poll, 100);
    return;
  }
  report();
}
window.addEventListener('load', poll);
