// Run axe-core (injected from the project's own copy) on the whole page, WCAG 2.0/2.1 A and AA
// rules only; every node found is sorted into the course's content (inside `content`, a CSS
// selector: the site's page body, or the notebook's outputs and rendered markdown) or the page's
// chrome (`notContent`: JupyterLab's own widgets inside a cell, e.g. the heading fold button).
async ([content, tags, notContent]) => {
  const result = await axe.run(document, {runOnly: {type: 'tag', values: tags},
                                          resultTypes: ['violations', 'incomplete']});
  const where = node => {
    const target = node.target[node.target.length - 1];
    let el = null;
    try { el = typeof target === 'string' ? document.querySelector(target) : null; } catch (e) {}
    const own = el && notContent && el.closest(notContent);
    return el && el.closest(content) && !own ? 'content' : 'chrome';
  };
  const sort = list => list.map(rule => ({
    id: rule.id, impact: rule.impact, help: rule.help,
    nodes: rule.nodes.map(n => ({where: where(n), target: JSON.stringify(n.target),
                                 html: n.html.slice(0, 200),
                                 why: (n.failureSummary || '').slice(0, 300)})),
  }));
  return {violations: sort(result.violations), incomplete: sort(result.incomplete)};
}
