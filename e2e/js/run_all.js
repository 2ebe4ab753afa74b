// Start "run all cells"; not awaited: the promise resolves only when every cell has run.
() => {
  window.jupyterapp.commands.execute('notebook:run-all-cells');
  return true;
}
