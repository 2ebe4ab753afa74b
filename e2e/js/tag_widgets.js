// Tag every top-level slider widget (an explorer box) so Playwright can address it.
() => {
  const w = window.__e2e_nb;
  const boxes = Array.from(w.content.node.querySelectorAll('.jp-OutputArea-child .jupyter-widgets'))
    .filter(b => b.querySelector('.widget-slider') && !b.parentElement.closest('.jupyter-widgets'));
  boxes.forEach((b, k) => b.setAttribute('data-e2e-widget', String(k)));
  return boxes.length;
}
