// The Cards view (the "Cards" display toggle): the converged hair drawn as the hair cards the
// export writes, at the Export menu's card count, so a user sees what a game will show. The
// status element carries data-cards and data-card-triangles while cards are on screen.
import type { Editor } from '../editor/editor';
import type { HairView } from '../viewer/hairView';
import type { ViewStore } from './viewState';

export function wireCardsView(d: {
  view: ViewStore;
  editor: Editor;
  hairView: HairView;
  statusElement: HTMLElement;
}): void {
  const { view, editor, hairView, statusElement } = d;
  hairView.onCards = (shown) => {
    if (shown) {
      statusElement.dataset.cards = String(shown.cards);
      statusElement.dataset.cardTriangles = String(shown.triangles);
    } else {
      delete statusElement.dataset.cards;
      delete statusElement.dataset.cardTriangles;
    }
  };
  const apply = () =>
    hairView.setCards(
      view.state.display.cards
        ? { count: view.state.cardCount, growth: editor.session.growth }
        : null,
    );
  view.listen(apply);
  editor.listen((c) => {
    if (c.sessionChanged) apply();
  });
  apply();
}
