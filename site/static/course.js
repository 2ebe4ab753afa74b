// Keyboard access to every box that scrolls sideways (WCAG 2.1.1): a wide formula, code block or
// output that scrolls inside its own box (course.css) gets a tab stop, so the arrow keys scroll it.
(function () {
  const boxes = 'div.body pre, div.body mjx-container[display="true"], div.body table, ' +
    'div.cell_output, div.output, div.animation';
  function focusable() {
    document.querySelectorAll(boxes).forEach(function (el) {
      if (el.scrollWidth > el.clientWidth + 1 && !el.hasAttribute('tabindex')) {
        el.setAttribute('tabindex', '0');
        if (!el.hasAttribute('role')) el.setAttribute('role', 'region');
        if (!el.hasAttribute('aria-label')) el.setAttribute('aria-label', 'scrollable content');
      }
    });
  }
  window.addEventListener('load', function () {
    focusable();
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(focusable);
    }
  });
  window.addEventListener('resize', focusable);
})();
