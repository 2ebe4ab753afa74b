// Run IBM's Equal Access engine (accessibility-checker-engine's ace.js, injected from the
// project's own copy) on the whole page with policy WCAG_2_1. A failure is a result with
// value ["VIOLATION", "FAIL"]; "POTENTIAL" and "MANUAL" results are needs-review (counted as
// incomplete). Each node (an XPath, `path.dom`) is sorted into content / chrome as in axe_run.js.
async ([content, notContent]) => {
  const report = await new ace.Checker().check(document, ['WCAG_2_1']);
  const where = r => {
    let el = null;
    try {
      el = document.evaluate(r.path.dom, document, null,
                             XPathResult.FIRST_ORDERED_NODE_TYPE, null).singleNodeValue;
    } catch (e) {}
    if (el && el.nodeType !== 1) el = el.parentElement;
    const own = el && notContent && el.closest(notContent);
    return el && el.closest(content) && !own ? 'content' : 'chrome';
  };
  const group = outcome => {
    const rules = {};
    for (const r of report.results) {
      if (r.value[0] !== 'VIOLATION' || !outcome(r.value[1])) continue;
      const rule = rules[r.ruleId] || (rules[r.ruleId] = {
        id: r.ruleId, impact: r.value[1], help: r.message, nodes: []});
      rule.nodes.push({where: where(r), target: r.path.dom, html: (r.snippet || '').slice(0, 200),
                       why: (r.message || '').slice(0, 300)});
    }
    return Object.values(rules);
  };
  return {violations: group(v => v === 'FAIL'),
          incomplete: group(v => v === 'POTENTIAL' || v === 'MANUAL')};
}
