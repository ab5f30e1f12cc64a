// The chart checker that tests/charts/run_chart_test.sh runs in headless
// Chromium on a page holding one chart (inline SVG). It writes its verdict
// into <pre id="verdict">: "PASS <counts>" or "FAIL <problem>; <problem>...".
// It checks what the reader sees, with the browser's own font metrics:
//  - no two non-empty <text> elements' boxes (getBoundingClientRect)
//    overlap by more than half a pixel in both directions;
//  - each curve (class "curve", data-series N) has a length, no two curves
//    share a style (stroke colour, stroke-dasharray, marker shape), and at
//    least one of its markers (class "marker", data-series N) is the topmost
//    element at its centre, i.e. it is not hidden under other curves' marks;
//  - each point of a scatter (class "point") is the topmost element at its centre.
(function () {
  const problems = [];
  const svg = document.querySelector('svg');
  const texts = Array.from(svg.querySelectorAll('text')).filter((t) => t.textContent.trim() !== '');
  const boxes = texts.map((t) => t.getBoundingClientRect());
  for (let i = 0; i < texts.length; ++i) {
    for (let j = i + 1; j < texts.length; ++j) {
      const a = boxes[i], b = boxes[j];
      const w = Math.min(a.right, b.right) - Math.max(a.left, b.left);
      const h = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
      if (w > 0.5 && h > 0.5) problems.push(`labels overlap: "${texts[i].textContent}" x "${texts[j].textContent}"`);
    }
  }
  const centre = (e) => {
    const r = e.getBoundingClientRect();
    return [(r.left + r.right) / 2, (r.top + r.bottom) / 2];
  };
  const curves = Array.from(svg.querySelectorAll('.curve'));
  const styles = new Map();
  for (const c of curves) {
    const s = c.getAttribute('data-series');
    const markers = Array.from(svg.querySelectorAll(`.marker[data-series="${s}"]`));
    if (!(c.getTotalLength() > 0)) problems.push(`curve ${s} has no length`);
    const style = [c.getAttribute('stroke'), c.getAttribute('stroke-dasharray') || 'solid',
                   markers.length ? markers[0].getAttribute('data-shape') : 'no marker'].join(' ');
    if (styles.has(style)) problems.push(`curves ${styles.get(style)} and ${s} share a style (${style})`);
    styles.set(style, s);
    const visible = markers.filter((m) => {
      const top = document.elementFromPoint(...centre(m));
      return top !== null && top.classList.contains('marker') && top.getAttribute('data-series') === s;
    });
    if (visible.length === 0) problems.push(`curve ${s} is hidden: none of its ${markers.length} markers is on top`);
  }
  const points = Array.from(svg.querySelectorAll('.point'));
  for (const p of points) {
    if (document.elementFromPoint(...centre(p)) !== p) problems.push(`point ${p.getAttribute('data-id')} is covered`);
  }
  document.getElementById('verdict').textContent = problems.length
      ? 'FAIL ' + problems.join('; ')
      : `PASS ${texts.length} labels disjoint, ${curves.length} curves visible, ${points.length} points visible`;
})();
