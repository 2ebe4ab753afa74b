// Where the live figure of widget k is on the page: the ipympl canvas that takes the mouse
// (the top one of the two) scrolled into view, as a client rectangle.
(k) => {
  const box = document.querySelector(`[data-e2e-widget="${k}"]`);
  const canvases = box ? box.querySelectorAll('.jupyter-matplotlib-canvas-div canvas') : [];
  if (canvases.length === 0) return null;
  const top = canvases[canvases.length - 1];
  top.scrollIntoView({block: 'center'});
  const r = top.getBoundingClientRect();
  return {x: r.x, y: r.y, width: r.width, height: r.height};
}
