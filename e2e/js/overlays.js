// The texts of the dialogs and notifications on screen.
() => {
  const texts = sel => Array.from(document.querySelectorAll(sel))
    .filter(e => e.offsetParent !== null || getComputedStyle(e).position === 'fixed')
    .map(e => e.innerText.trim().slice(0, 300));
  return {dialogs: texts('.jp-Dialog'), toasts: texts('.Toastify__toast')};
}
