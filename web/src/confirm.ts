// A confirmation dialog (the native <dialog>, modal): focus goes to it,
// Tab stays inside, Escape or Cancel answers no, the confirming button yes.
import { h } from './dom';

// The dialog; `extra` goes between the detail and the buttons, and the
// answer is made by `yes()` when the confirming button is pressed.
function ask<T>(title: string, detail: string, confirmLabel: string, extra: HTMLElement | null, yes: () => T, no: T, focus?: HTMLElement): Promise<T> {
  return new Promise((answer) => {
    const confirm = h('button', { type: 'submit', value: 'yes', text: confirmLabel });
    const cancel = h('button', { type: 'button', text: 'Cancel' });
    const dialog = h(
      'dialog',
      { class: 'confirm', 'aria-labelledby': 'confirm-h', 'aria-describedby': 'confirm-d' },
      h('form', { method: 'dialog' }, h('h2', { id: 'confirm-h', text: title }), h('p', { id: 'confirm-d', text: detail }), extra, h('div', { class: 'buttons' }, confirm, cancel)),
    );
    let said = false;
    const done = (value: T) => {
      if (said) return;
      said = true;
      dialog.close();
      dialog.remove();
      answer(value);
    };
    dialog.addEventListener('submit', (e) => {
      e.preventDefault();
      done(yes());
    });
    cancel.addEventListener('click', () => done(no));
    dialog.addEventListener('cancel', (e) => {
      e.preventDefault(); // Escape
      done(no);
    });
    document.body.append(dialog);
    dialog.showModal();
    // The safe answer has the focus: Enter alone never sends to a machine.
    (focus ?? cancel).focus();
  });
}

export function confirmAction(title: string, detail: string, confirmLabel: string): Promise<boolean> {
  return ask(title, detail, confirmLabel, null, () => true, false);
}

// The same, with a reason typed in the dialog (for the audit log): the
// reason when confirmed (may be empty), null when cancelled. The reason's
// field has the focus; Enter in it confirms, as a form's Enter does.
export function confirmWithReason(title: string, detail: string, confirmLabel: string, reasonLabel: string): Promise<string | null> {
  const reason = h('input', { type: 'text', id: 'confirm-reason', maxlength: 2000, autocomplete: 'off' });
  const field = h('div', { class: 'field' }, h('label', { for: 'confirm-reason', text: reasonLabel }), reason);
  return ask<string | null>(title, detail, confirmLabel, field, () => reason.value.trim(), null, reason);
}
