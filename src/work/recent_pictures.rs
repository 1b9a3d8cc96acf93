//! The pictures of tiles drawn lately, by the link they were grown from: a tile asked again (a
//! parent that was an offspring, a generation gone back to, a map drawn again) is shown at
//! once. The page keeps each picture as an address the browser holds the image under; each
//! address this lets go is handed back, for the page to release.

use std::collections::VecDeque;

/// Pictures kept, the oldest let go past [`RecentPictures::KEPT`]: `U` is how the page holds
/// one (an object URL).
#[derive(Debug)]
pub struct RecentPictures<U> {
    kept: VecDeque<(String, U)>,
}

impl<U> Default for RecentPictures<U> {
    fn default() -> Self {
        Self {
            kept: VecDeque::new(),
        }
    }
}

impl<U> RecentPictures<U> {
    /// Most pictures kept.
    pub const KEPT: usize = 256;

    /// The picture of `link`, if kept.
    pub fn get(&self, link: &str) -> Option<&U> {
        self.kept.iter().find(|(l, _)| l == link).map(|(_, u)| u)
    }

    /// Keeps `picture` as the picture of `link`; what is let go for it (the picture of `link`
    /// kept before, or the oldest when too many are kept), to be released.
    pub fn keep(&mut self, link: String, picture: U) -> Option<U> {
        let gone = self.forget(&link).or_else(|| {
            (self.kept.len() >= Self::KEPT)
                .then(|| self.kept.pop_front())
                .flatten()
                .map(|(_, u)| u)
        });
        self.kept.push_back((link, picture));
        gone
    }

    /// Lets the picture of `link` go (one a lost device may have drawn blank), to be drawn
    /// again; it is returned, to be released.
    pub fn forget(&mut self, link: &str) -> Option<U> {
        let at = self.kept.iter().position(|(l, _)| l == link)?;
        self.kept.remove(at).map(|(_, u)| u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_picture_let_go_is_handed_back_once_and_a_link_is_kept_once() {
        let mut recent = RecentPictures::default();
        let mut released = Vec::new();
        for n in 0..RecentPictures::<u32>::KEPT as u32 + 10 {
            released.extend(recent.keep(format!("link {n}"), n));
        }
        // The ten oldest went, in order; the newest are kept.
        assert_eq!(released, (0..10).collect::<Vec<_>>());
        assert_eq!(recent.get("link 9"), None);
        assert_eq!(recent.get("link 10"), Some(&10));
        // Drawn again, a link's picture replaces its last, which is handed back.
        assert_eq!(recent.keep("link 10".into(), 1000), Some(10));
        assert_eq!(recent.get("link 10"), Some(&1000));
        assert_eq!(recent.kept.len(), RecentPictures::<u32>::KEPT);
        // Forgotten, it is handed back, and is gone.
        assert_eq!(recent.forget("link 10"), Some(1000));
        assert_eq!(recent.forget("link 10"), None);
        assert_eq!(recent.get("link 10"), None);
        // Under the cap, nothing more is let go.
        assert_eq!(recent.keep("link 10".into(), 7), None);
    }
}
