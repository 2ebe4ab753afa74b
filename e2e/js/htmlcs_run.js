// Run HTML_CodeSniffer (pa11y's engine; HTMLCS.js injected from the project's own copy) on the
// page with its WCAG2AA standard, as pa11y does. Its errors (type 1) are the failures, its
// warnings (type 2) needs-review; notices (type 3, "check this by hand") are left out, as pa11y
// leaves them out by default. Each element is sorted into content / chrome as in axe_run.js.
([content, notContent]) => new Promise((resolve, reject) => {
  const done = () => {
    const where = el => {
      if (el && el.nodeType !== 1) el = el.parentElement;
      const own = el && el.closest && notContent && el.closest(notContent);
      return el && el.closest && el.closest(content) && !own ? 'content' : 'chrome';
    };
    const html = el => (el && el.outerHTML ? el.outerHTML : String(el)).slice(0, 200);
    const group = type => {
      const rules = {};
      for (const m of HTMLCS.getMessages()) {
        if (m.type !== type) continue;
        const rule = rules[m.code] || (rules[m.code] = {
          id: m.code, impact: type === 1 ? 'error' : 'warning', help: m.msg, nodes: []});
        rule.nodes.push({where: where(m.element), target: '', html: html(m.element),
                         why: m.msg.slice(0, 300)});
      }
      return Object.values(rules);
    };
    resolve({violations: group(1), incomplete: group(2)});
  };
  try { HTMLCS.process('WCAG2AA', document, done, reject, 'en'); } catch (e) { reject(e); }
})
