// Scroll through the whole notebook a screenful at a time, as a student reading it would,
// giving JupyterLab's windowing a few frames at each stop to render what came into view;
// then back to the top. Resolves to the number of stops.
async () => {
  const w = window.__e2e_nb;
  const nodes = [w.content.node, ...w.content.node.querySelectorAll('.jp-WindowedPanel-outer')];
  const el = nodes.reduce((a, b) => (b.scrollHeight > a.scrollHeight ? b : a));
  const frames = n => new Promise(r => {
    const step = k => (k === 0 ? r() : requestAnimationFrame(() => step(k - 1)));
    step(n);
  });
  let stops = 0;
  for (let top = 0; top < el.scrollHeight; top += Math.max(200, el.clientHeight * 0.9)) {
    el.scrollTop = top;
    await frames(4);
    stops++;
  }
  el.scrollTop = 0;
  await frames(2);
  return stops;
}
