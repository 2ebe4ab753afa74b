// The notebook model: kernel status, and per cell its type, source, count, state and outputs.
() => {
  const w = window.__e2e_nb;
  const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
  const cells = [];
  const model = w.content.model;
  for (let i = 0; i < model.cells.length; i++) {
    const c = model.cells.get(i);
    const info = {type: c.type, source: c.sharedModel.getSource()};
    if (c.type === 'code') {
      info.count = c.executionCount;
      info.state = c.executionState || null;
      info.outputs = [];
      for (let j = 0; j < c.outputs.length; j++) {
        const o = c.outputs.get(j).toJSON();
        const mimes = Object.keys(o.data || {});
        let text = '';
        if (o.output_type === 'error') text = o.ename + ': ' + o.evalue;
        else if (o.output_type === 'stream') text = Array.isArray(o.text) ? o.text.join('') : o.text;
        info.outputs.push({type: o.output_type, name: o.name || null, mimes: mimes, text: text});
      }
    }
    cells.push(info);
  }
  return {kernel: kernel ? kernel.status : 'none', cells: cells};
}
