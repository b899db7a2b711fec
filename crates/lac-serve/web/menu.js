// A control point's menu (right click on the point, or the context-menu key or Shift+F10 for
// the selected point, in a mode that has one: modes/ `menu`): buttons in a box at the point,
// the current choice marked and focused. The arrow keys, Home and End move between the
// buttons, Enter or Space chooses one (which closes the menu), Escape, Tab, a click elsewhere,
// the wheel or a resize close it; the focus goes back where it was.

import { $ } from './state.js';

let current = null; // {box, previous, onDocument, onWindow}

/** Whether the menu is open (tests, and the keys that open it). */
export const menuOpen = () => current !== null;

/** Close the menu (nothing when none is open); the focus goes back where it was. */
export function closeMenu() {
  if (!current) return;
  const { box, previous, onDocument, onWindow } = current;
  current = null;
  document.removeEventListener('pointerdown', onDocument, true);
  window.removeEventListener('resize', onWindow);
  window.removeEventListener('wheel', onWindow, true);
  box.remove();
  if (previous && previous.isConnected && typeof previous.focus === 'function') previous.focus();
}

/**
 * Open the menu `{title, items}` (modes/: `menu`) at client position (`x`, `y`), inside the
 * stage; `choose(item)` is called with the button chosen, after the menu closed.
 */
export function openMenu({ title, items }, x, y, choose) {
  closeMenu();
  const stage = $('stage');
  const box = document.createElement('div');
  box.id = 'point-menu';
  box.setAttribute('role', 'menu');
  const heading = document.createElement('div');
  heading.id = 'point-menu-title';
  heading.className = 'menu-title';
  heading.textContent = title;
  box.setAttribute('aria-labelledby', heading.id);
  box.append(heading);
  const buttons = items.map((item) => {
    const button = document.createElement('button');
    button.type = 'button';
    button.setAttribute('role', item.checkbox ? 'menuitemcheckbox' : 'menuitemradio');
    button.setAttribute('aria-checked', String(!!item.checked));
    button.setAttribute('aria-keyshortcuts', item.key);
    button.dataset.key = item.key;
    button.disabled = !!item.disabled;
    button.tabIndex = -1;
    const mark = document.createElement('span');
    mark.className = 'mark';
    mark.setAttribute('aria-hidden', 'true');
    mark.textContent = item.checked ? (item.checkbox ? '✓' : '●') : '';
    const label = document.createElement('span');
    label.className = 'label';
    label.textContent = item.label;
    const key = document.createElement('kbd');
    key.setAttribute('aria-hidden', 'true');
    key.textContent = item.key;
    button.append(mark, label, key);
    button.addEventListener('click', () => {
      closeMenu();
      choose(item);
    });
    box.append(button);
    return button;
  });
  box.addEventListener('contextmenu', (e) => e.preventDefault());
  box.addEventListener('keydown', (e) => {
    const enabled = buttons.filter((b) => !b.disabled);
    const at = enabled.indexOf(document.activeElement);
    const move = { ArrowDown: at + 1, ArrowUp: at - 1, Home: 0, End: enabled.length - 1 }[e.key];
    if (move !== undefined) {
      enabled[(move + enabled.length) % enabled.length].focus();
    } else if (e.key === 'Escape' || e.key === 'Tab') {
      closeMenu();
    } else {
      // A button's letter chooses it, as the same key does on the selected point.
      const letter = enabled.find((b) => b.dataset.key.toLowerCase() === e.key.toLowerCase());
      if (!letter || e.ctrlKey || e.metaKey || e.altKey) return;
      letter.click();
    }
    e.preventDefault();
    e.stopPropagation();
  });
  stage.append(box);
  // At the pointer, kept inside the stage.
  const area = stage.getBoundingClientRect();
  const left = Math.max(4, Math.min(x - area.left + 4, area.width - box.offsetWidth - 4));
  const top = Math.max(4, Math.min(y - area.top + 4, area.height - box.offsetHeight - 4));
  box.style.left = `${left}px`;
  box.style.top = `${top}px`;
  const onDocument = (e) => {
    if (!box.contains(e.target)) closeMenu();
  };
  const onWindow = () => closeMenu();
  current = { box, previous: document.activeElement, onDocument, onWindow };
  document.addEventListener('pointerdown', onDocument, true);
  window.addEventListener('resize', onWindow);
  window.addEventListener('wheel', onWindow, true);
  const first = buttons.find((b) => !b.disabled && b.getAttribute('aria-checked') === 'true' && b.getAttribute('role') === 'menuitemradio')
    || buttons.find((b) => !b.disabled);
  if (first) first.focus();
}
