// The figure of widget k as it is drawn now, the readout of its slider s, and the times (page
// clock, ms) of the last release of the mouse button and of the first redraw of the figure's
// canvas after it (timing_hooks.js records them).
// The figure is an ipympl canvas (its pixels, as a data URL) or else an <img>.
([k, s]) => {
  const box = document.querySelector(`[data-e2e-widget="${k}"]`);
  const canvas = box && box.querySelector('.jupyter-matplotlib-canvas-div canvas');
  const img = box && box.querySelector('img');
  const slider = box && box.querySelectorAll('.widget-slider')[s];
  const readout = slider && slider.querySelector('.widget-readout');
  let src = null, loaded = false;
  if (canvas && canvas.width > 0) {
    src = canvas.toDataURL();
    loaded = true;
  } else if (img) {
    src = img.getAttribute('src');
    loaded = img.complete && img.naturalWidth > 0;
  }
  const released = window.__e2e_released || 0;
  const math = box ? box.querySelectorAll('.widget-htmlmath').length : 0;
  return {
    src: src,
    loaded: loaded,
    canvas: !!canvas,
    readout: readout ? readout.textContent : null,
    stderr: box ? box.querySelectorAll('[data-mime-type="application/vnd.jupyter.stderr"]').length : 0,
    math: math,
    mathTypeset: box ? box.querySelectorAll('.widget-htmlmath mjx-container').length : 0,
    released: released,
    drawn: canvas ? ((canvas.__e2e_draws || []).find(t => t > released) || null) : null,
  };
}
