//! The doubts of a run's views, kept apart per view: a result states the first doubt of its
//! views taken in a fixed order (the first curve's before the second's, a profile's segments
//! in turn), not the first met in time, and two stretches of one curve share its doubts.

use crate::view::View;
use numeric::certificate::Doubts;
use smallvec::SmallVec;

/// Each view's doubts, by the view's [`View::book`]. Owned by the run that searches the
/// views; every step that may meet a doubt on a pair of views is handed it. (Empty books do
/// not allocate: a certified run allocates nothing for them.)
#[derive(Default)]
pub(crate) struct Ledger {
    books: SmallVec<[Doubts; 2]>,
}

impl Ledger {
    /// No doubt yet on any view.
    pub(crate) fn new() -> Self {
        Self::default()
    }

    /// The doubts of the view kept in book `book`.
    pub(crate) fn book(&mut self, book: usize) -> &mut Doubts {
        if self.books.len() <= book {
            self.books.resize_with(book + 1, Doubts::none);
        }
        &mut self.books[book]
    }

    /// The doubts of `view`.
    pub(crate) fn of(&mut self, view: &View) -> &mut Doubts {
        self.book(view.book)
    }

    /// The doubts of book `book`, leaving it empty.
    pub(crate) fn take(&mut self, book: usize) -> Doubts {
        std::mem::take(self.book(book))
    }
}
