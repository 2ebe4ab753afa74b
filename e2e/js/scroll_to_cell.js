// Scroll cell i into the middle of the view, as a student scrolling down would, and wait two
// frames for JupyterLab's windowing to attach and render it. Resolves to whether it is attached.
async (i) => {
  const w = window.__e2e_nb;
  const cell = w.content.widgets[i];
  try {
    await Promise.race([w.content.scrollToItem(i, 'center'),
                        new Promise(resolve => setTimeout(resolve, 5000))]);
  } catch (e) { /* fall back to the DOM below */ }
  if (cell.node.isConnected) cell.node.scrollIntoView({block: 'center'});
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  return cell.node.isConnected;
}
