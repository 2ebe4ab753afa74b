// The element that scrolls the notebook: the notebook node or, in JupyterLab 4, its outer
// panel. Optionally scroll it to `top`; report its geometry.
(top) => {
  const w = window.__e2e_nb;
  if (!w) return null;
  const nodes = [w.content.node, ...w.content.node.querySelectorAll('.jp-WindowedPanel-outer')];
  const el = nodes.reduce((a, b) => (b.scrollHeight > a.scrollHeight ? b : a));
  if (top !== null) {
    for (const n of nodes) n.scrollTop = 0;
    el.scrollTop = top;
    if (document.activeElement) document.activeElement.blur();
  }
  const r = el.getBoundingClientRect();
  return {scrollHeight: el.scrollHeight, clientHeight: el.clientHeight, scrollTop: el.scrollTop,
          top: Math.round(r.top), viewport: window.innerHeight};
}
