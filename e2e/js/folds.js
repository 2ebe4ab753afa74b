// The folded headings of the notebook (markdown cells with metadata
// "jp-MarkdownHeadingCollapsed": true) as JupyterLab shows them: per fold its cell, level,
// whether JupyterLab has it collapsed, and the cells under it (up to the next heading of the
// same or a higher level) with whether each is hidden. Tags the button a student clicks to
// expand it (data-e2e-fold="<cell index>"): the "N cells hidden" button under the heading, or
// else the heading's own collapse button. `indices`: the heading cells to report (null: those
// with the metadata; JupyterLab drops it from a heading once expanded).
(indices) => {
  const w = window.__e2e_nb;
  const cells = w.content.widgets;
  const level = c => (c.model.type === 'markdown' && c.headingInfo) ? c.headingInfo.level : 0;
  const folds = [];
  document.querySelectorAll('[data-e2e-fold]').forEach(b => b.removeAttribute('data-e2e-fold'));
  cells.forEach((cell, i) => {
    if (cell.model.type !== 'markdown') return;
    if (indices === null ? !cell.model.getMetadata('jp-MarkdownHeadingCollapsed')
                         : !indices.includes(i)) return;
    const lv = level(cell);
    const under = [];
    for (let j = i + 1; j < cells.length; j++) {
      const l = level(cells[j]);
      if (l > 0 && lv > 0 && l <= lv) break;
      under.push({i: j, hidden: cells[j].isHidden});
    }
    const shown = b => b && getComputedStyle(b).display !== 'none';
    const button = [cell.node.querySelector('.jp-showHiddenCellsButton'),
                    cell.node.querySelector('.jp-collapseHeadingButton')].find(shown);
    if (button) button.setAttribute('data-e2e-fold', String(i));
    folds.push({i: i, level: lv, collapsed: !!cell.headingCollapsed, under: under,
                button: !!button, next: i + 1 + under.length < cells.length ? i + 1 + under.length : null,
                nextHidden: i + 1 + under.length < cells.length ? cells[i + 1 + under.length].isHidden : null});
  });
  return folds;
}
