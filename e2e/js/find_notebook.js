// Find the notebook panel open on `path`; true once its context is ready and its kernel idle.
// Remembers the panel as window.__e2e_nb for the other scripts.
(path) => {
  const app = window.jupyterapp;
  if (!app || !app.shell) return false;
  for (const w of app.shell.widgets('main')) {
    if (w.context && w.context.path === path && w.content && w.content.model) {
      if (!w.context.isReady) return false;
      const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
      if (!kernel || kernel.status !== 'idle') return false;
      window.__e2e_nb = w;
      app.shell.activateById(w.id);
      app.shell.collapseLeft();  // the file browser adds nothing to the screenshots
      return true;
    }
  }
  return false;
}
