// Per cell, what the page shows (output children map one-to-one onto the model's outputs):
// typeset math, images (own and inside widgets), widgets, sliders and live figure canvases.
() => {
  const w = window.__e2e_nb;
  const loaded = im => im.complete && im.naturalWidth > 0;
  const cells = [];
  w.content.widgets.forEach((cell) => {
    const node = cell.node;
    const info = {
      mjx: node.querySelectorAll('.jp-MarkdownOutput mjx-container').length,
      merror: node.querySelectorAll('mjx-merror').length,
      rendered: node.classList.contains('jp-mod-rendered'),
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
        info.outputs.push({
          imgs: own.length,
          loaded: own.filter(loaded).length,
          widget: !!widget,
          widgetText: widget ? widget.innerText.slice(0, 200) : '',
          sliders: child.querySelectorAll('.widget-slider').length,
          widgetImgs: inWidget.length,
          widgetLoaded: inWidget.filter(loaded).length,
          canvases: canvases.filter(c => c.width > 0 && c.height > 0).length,
        });
      }
    }
    cells.push(info);
  });
  const errs = Array.from(document.querySelectorAll(
    '.jp-NotebookPanel [data-mime-type="application/vnd.jupyter.stderr"]'));
  const broken = Array.from(document.querySelectorAll('.jp-NotebookPanel img'))
    .filter(im => im.complete && im.naturalWidth === 0 && im.getAttribute('src'));
  return {
    cells: cells,
    stderr: errs.map(e => e.innerText.slice(0, 500)),
    broken: broken.map(im => (im.getAttribute('src') || '').slice(0, 80)),
    widgetErrors: Array.from(document.querySelectorAll('.jp-NotebookPanel .jupyter-widgets'))
      .map(e => e.innerText).filter(t => t.includes('Error displaying widget')
        || t.includes('Error rendering widget') || t.includes('model not found')),
  };
}
