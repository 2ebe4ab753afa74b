// Installed before the page's own scripts: remember when the mouse button was last released
// and when each canvas was last drawn on, so that the runner can time slider release ->
// redrawn figure with the page's clock.
(() => {
  const draw = CanvasRenderingContext2D.prototype.drawImage;
  CanvasRenderingContext2D.prototype.drawImage = function (...args) {
    if (this.canvas) {
      const draws = this.canvas.__e2e_draws || (this.canvas.__e2e_draws = []);
      draws.push(performance.now());
      if (draws.length > 100) draws.shift();
    }
    return draw.apply(this, args);
  };
  const released = () => { window.__e2e_released = performance.now(); };
  window.addEventListener('pointerup', released, true);
  window.addEventListener('mouseup', released, true);
})();
