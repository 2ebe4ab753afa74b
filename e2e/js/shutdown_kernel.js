// Shut the notebook's kernel down (the runner closes the page afterwards).
() => window.__e2e_nb && window.__e2e_nb.sessionContext.shutdown()
