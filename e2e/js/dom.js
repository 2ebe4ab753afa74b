// Per cell, what the page shows (output children map one-to-one onto the model's outputs):
// typeset math, images (own and inside widgets) with their rendered sizes, widgets, sliders
// and live figure canvases, and matplotlib's animation player. `indices`: the cells to look at
// (null: all of them). With JupyterLab's windowing a cell off screen may not be rendered yet:
// the runner scrolls such cells into view (scroll_to_cell.js) and looks again.
(indices) => {
  const w = window.__e2e_nb;
  const loaded = im => im.complete && im.naturalWidth > 0;
  const size = el => { const r = el.getBoundingClientRect(); return [r.width, r.height]; };
  const shown = im => { const [x, y] = size(im); return x > 0 && y > 0; };
  const cells = [];
  const all = w.content.widgets;
  for (const i of (indices === null ? all.map((_, k) => k) : indices)) {
    const node = all[i].node;
    const info = {
      i: i,
      mjx: node.querySelectorAll('.jp-MarkdownOutput mjx-container').length,
      merror: node.querySelectorAll('mjx-merror').length,
      attached: node.isConnected,
      outputs: [],
    };
    const area = node.querySelector('.jp-OutputArea');
    if (area) {
      for (const child of area.querySelectorAll(':scope > .jp-OutputArea-child')) {
        const imgs = Array.from(child.querySelectorAll('img'));
        const own = imgs.filter(im => !im.closest('.jupyter-widgets'));
        const inWidget = imgs.filter(im => im.closest('.jupyter-widgets'));
        const widget = child.querySelector('.jupyter-widgets');
        const canvases = Array.from(child.querySelectorAll('.jupyter-matplotlib-canvas-div canvas'));
        // Untrusted (on opening) JupyterLab's sanitizer turns the id into data-jupyter-id.
        const player = child.querySelector(
          'img[id^="_anim_img"], img[data-jupyter-id^="_anim_img"]');
        info.outputs.push({
          imgs: own.length,
          loaded: own.filter(loaded).length,
          shown: own.filter(im => loaded(im) && shown(im)).length,
          widget: !!widget,
          sliders: child.querySelectorAll('.widget-slider').length,
          widgetImgs: inWidget.length,
          widgetLoaded: inWidget.filter(loaded).length,
          canvases: canvases.filter(c => c.width > 0 && c.height > 0).length,
          player: player ? {
            size: size(player).map(Math.round),
            loaded: loaded(player),
            src: (player.getAttribute('src') || '').slice(0, 40),
          } : null,
        });
      }
    }
    cells.push(info);
  }
  const errs = Array.from(document.querySelectorAll(
    '.jp-NotebookPanel [data-mime-type="application/vnd.jupyter.stderr"]'));
  const broken = Array.from(document.querySelectorAll('.jp-NotebookPanel img'))
    .filter(im => im.complete && im.naturalWidth === 0 && im.getAttribute('src'));
  return {
    n: all.length,
    cells: cells,
    stderr: errs.map(e => e.textContent.slice(0, 500)),
    broken: broken.map(im => (im.getAttribute('src') || '').slice(0, 80)),
    widgetErrors: Array.from(document.querySelectorAll('.jp-NotebookPanel .jupyter-widgets'))
      .map(e => e.textContent).filter(t => t.includes('Error displaying widget')
        || t.includes('Error rendering widget') || t.includes('model not found')),
  };
}
