// A confirmation dialog (the native <dialog>, modal): focus goes to it,
// Tab stays inside, Escape or Cancel answers no, the confirming button yes.
import { h } from './dom';

export function confirmAction(title: string, detail: string, confirmLabel: string): Promise<boolean> {
  return new Promise((answer) => {
    const yes = h('button', { type: 'submit', value: 'yes', text: confirmLabel });
    const no = h('button', { type: 'button', text: 'Cancel' });
    const dialog = h(
      'dialog',
      { class: 'confirm', 'aria-labelledby': 'confirm-h', 'aria-describedby': 'confirm-d' },
      h('form', { method: 'dialog' }, h('h2', { id: 'confirm-h', text: title }), h('p', { id: 'confirm-d', text: detail }), h('div', { class: 'buttons' }, yes, no)),
    );
    let said = false;
    const done = (ok: boolean) => {
      if (said) return;
      said = true;
      dialog.close();
      dialog.remove();
      answer(ok);
    };
    dialog.addEventListener('submit', (e) => {
      e.preventDefault();
      done(true);
    });
    no.addEventListener('click', () => done(false));
    dialog.addEventListener('cancel', (e) => {
      e.preventDefault(); // Escape
      done(false);
    });
    document.body.append(dialog);
    dialog.showModal();
    no.focus(); // the safe answer has the focus: Enter alone never sends to a machine
  });
}
