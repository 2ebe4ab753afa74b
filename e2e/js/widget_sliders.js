// The labels (descriptions) of the sliders of widget k, in order.
(k) => {
  const box = document.querySelector(`[data-e2e-widget="${k}"]`);
  return box ? Array.from(box.querySelectorAll('.widget-slider')).map(s => {
    const label = s.querySelector('.widget-label');
    return label ? label.textContent.trim() : '';
  }) : [];
}
