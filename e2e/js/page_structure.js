// What axe's WCAG tags leave to best practice, read from the page: the language, the headings
// (levels in order, one h1) and the text of every link (its accessible name).
(content) => {
  const root = document.querySelector(content) || document.body;
  const visible = el => !el.closest('[hidden], [aria-hidden="true"]');
  const headings = [...root.querySelectorAll('h1, h2, h3, h4, h5, h6')].filter(visible)
    .map(h => ({level: Number(h.tagName[1]), text: h.textContent.trim().slice(0, 80)}));
  const links = [...root.querySelectorAll('a[href]')].filter(visible).map(a => ({
    text: (a.getAttribute('aria-label') || a.textContent || a.title ||
           [...a.querySelectorAll('img[alt]')].map(i => i.alt).join(' ')).trim(),
    href: a.getAttribute('href')}));
  return {lang: document.documentElement.lang, headings, links,
          h1: document.querySelectorAll('h1').length};
}
