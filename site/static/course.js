// Keyboard access to every box that scrolls sideways (WCAG 2.1.1): a wide formula, code block or
// output that scrolls inside its own box (course.css) gets a tab stop, so the arrow keys scroll
// it, the role region and a name of its own (WCAG 4.1.2: IBM's engine fails regions that share
// one name): what it is, its number on the page, and its first words ("formula 3: R equals ...",
// "code 2: import numpy as np", "output 4: ..."). Boxes that fit get none of it (at 320 px more
// boxes scroll: the names are set again on resize).
(function () {
  const kinds = [
    ['formula', 'div.body mjx-container'],
    ['code', 'div.body pre'],
    ['table', 'div.body table'],
    ['output', 'div.cell_output, div.output'],
    ['animation', 'div.animation'],
  ];
  function words(el, kind) {
    let text = '';
    if (kind === 'formula') {
      const mml = el.querySelector('mjx-assistive-mml');
      text = mml ? mml.textContent : '';
    } else if (kind === 'table') {
      const caption = el.querySelector('caption, th');
      text = caption ? caption.textContent : '';
    } else if (kind !== 'animation') {
      text = el.textContent;
    }
    text = text.replace(/\s+/g, ' ').trim();
    return text.length > 60 ? text.slice(0, 60).replace(/\s\S*$/, '') + ' …' : text;
  }
  function name(el, kind, n) {
    const what = words(el, kind);
    return 'scrollable ' + kind + ' ' + n + (what ? ': ' + what : '');
  }
  // An inline formula wider than its line: a box of its own that scrolls (course.css).
  function wideInline() {
    document.querySelectorAll('div.body mjx-container:not([display="true"])').forEach(
      function (el) {
        const line = el.parentElement.closest('p, li, dd, td, th, div, h1, h2, h3, h4, h5, h6');
        el.classList.remove('course-wide');
        if (line && el.getBoundingClientRect().width > line.clientWidth + 1) {
          el.classList.add('course-wide');
        }
      });
  }
  function focusable() {
    wideInline();
    kinds.forEach(function (pair) {
      let n = 0;
      document.querySelectorAll(pair[1]).forEach(function (el) {
        if (el.parentElement && el.parentElement.closest('[data-course-scroll]')) return;
        if (el.scrollWidth > el.clientWidth + 1) {
          n += 1;
          el.setAttribute('data-course-scroll', pair[0]);
          el.setAttribute('tabindex', '0');
          if (!el.hasAttribute('role')) {
            el.setAttribute('role', 'region');
            el.setAttribute('data-course-role', '');
          }
          el.setAttribute('aria-label', name(el, pair[0], n));
        } else if (el.getAttribute('data-course-scroll')) {
          el.removeAttribute('data-course-scroll');
          el.removeAttribute('tabindex');
          if (el.hasAttribute('data-course-role')) el.removeAttribute('role');
          el.removeAttribute('data-course-role');
          el.removeAttribute('aria-label');
        }
      });
    });
  }
  // A heading with maths (WCAG 1.3.1, 2.4.6): its accessible name is its text with each formula
  // read from MathJax's assistive MathML, one word per symbol ("the solution of q ˙ = ω ^ q"):
  // the CHTML glyphs are hidden from the accessibility tree and a heading's name would lose them.
  function mathWords(mml) {
    const leaves = [...mml.querySelectorAll('mi, mn, mo, mtext, ms')];
    return leaves.map(function (x) { return x.textContent.trim(); })
      .filter(Boolean).join(' ');
  }
  function headings() {
    document.querySelectorAll('div.body h1, div.body h2, div.body h3, div.body h4, ' +
                              'div.body h5, div.body h6').forEach(function (h) {
      if (!h.querySelector('mjx-container')) return;
      const copy = h.cloneNode(true);
      copy.querySelectorAll('a.headerlink').forEach(function (a) { a.remove(); });
      copy.querySelectorAll('mjx-container').forEach(function (m) {
        const mml = m.querySelector('mjx-assistive-mml');
        m.replaceWith(document.createTextNode(' ' + (mml ? mathWords(mml) : '') + ' '));
      });
      h.setAttribute('aria-label', copy.textContent.replace(/\s+/g, ' ').trim());
    });
  }
  let pending = null;
  window.addEventListener('load', function () {
    focusable();
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(function () { focusable(); headings(); });
    }
  });
  window.addEventListener('resize', function () {
    clearTimeout(pending);
    pending = setTimeout(focusable, 100);
  });
})();
