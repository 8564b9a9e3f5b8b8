//! The City's fixed-capacity tables filled by King's Pages 2, 5 and 10.

use crate::king_pages::{ActionReaction, AssignAction, EnvelopeAssignment, MinInterval};
use crate::letter::{Envelope, Reject};

/// One envelope assigned to a folder (King's Page 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Assignment {
    /// The envelope.
    pub envelope: Envelope,
    /// The C (compressed) flag it was assigned with.
    pub compressed: bool,
    /// The folder it is assigned to.
    pub folder: u8,
    /// D: the use of the envelope is enabled.
    pub enabled: bool,
}

/// Envelope-to-folder assignments, at most `N`.
///
/// An envelope has at most one assignment (the seed's "transfer the current
/// assignment of this envelope" presumes one); a folder may hold several
/// envelopes ("the previous assignment will be kept in parallel").
#[derive(Debug, Clone)]
pub struct FolderTable<const N: usize> {
    entries: [Option<Assignment>; N],
}

impl<const N: usize> Default for FolderTable<N> {
    fn default() -> Self {
        Self { entries: [None; N] }
    }
}

impl<const N: usize> FolderTable<N> {
    /// The assignment of `envelope`, if any.
    pub fn get(&self, envelope: Envelope) -> Option<&Assignment> {
        self.iter().find(|a| a.envelope == envelope)
    }

    /// All assignments.
    pub fn iter(&self) -> impl Iterator<Item = &Assignment> {
        self.entries.iter().flatten()
    }

    /// The envelopes assigned to `folder`.
    pub fn in_folder(&self, folder: u8) -> impl Iterator<Item = &Assignment> {
        self.iter().filter(move |a| a.folder == folder)
    }

    /// Number of assignments.
    pub fn len(&self) -> usize {
        self.iter().count()
    }

    /// `true` if there is no assignment.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn slot(&mut self, envelope: Envelope) -> Option<&mut Assignment> {
        self.entries
            .iter_mut()
            .flatten()
            .find(|a| a.envelope == envelope)
    }

    /// Apply King's Page 2. Nothing changes when it is rejected.
    ///
    /// Keep/Transfer of an unassigned envelope -> [`Reject::NotAssigned`];
    /// Assign of an envelope assigned to another folder ->
    /// [`Reject::AlreadyAssigned`] (re-assigning to the same folder updates
    /// D and C); no free entry -> [`Reject::TableFull`]; Expel of an
    /// unassigned envelope is accepted and changes nothing.
    pub fn apply(&mut self, page: &EnvelopeAssignment) -> Result<(), Reject> {
        let spec = page.envelope;
        match page.action {
            AssignAction::Keep { enable } => {
                let a = self.slot(spec.envelope).ok_or(Reject::NotAssigned)?;
                a.enabled = enable;
            }
            AssignAction::Transfer { folder, enable } => {
                let a = self.slot(spec.envelope).ok_or(Reject::NotAssigned)?;
                a.folder = folder;
                a.enabled = enable;
                a.compressed = spec.compressed;
            }
            AssignAction::Assign { folder, enable } => {
                if let Some(a) = self.slot(spec.envelope) {
                    if a.folder != folder {
                        return Err(Reject::AlreadyAssigned);
                    }
                    a.enabled = enable;
                    a.compressed = spec.compressed;
                } else {
                    let free = self
                        .entries
                        .iter_mut()
                        .find(|e| e.is_none())
                        .ok_or(Reject::TableFull)?;
                    *free = Some(Assignment {
                        envelope: spec.envelope,
                        compressed: spec.compressed,
                        folder,
                        enabled: enable,
                    });
                }
            }
            AssignAction::Expel => {
                for e in self.entries.iter_mut() {
                    if e.is_some_and(|a| a.envelope == spec.envelope) {
                        *e = None;
                    }
                }
            }
        }
        Ok(())
    }
}

/// Action/reaction links (King's Page 5), at most `N`.
#[derive(Debug, Clone)]
pub struct LinkTable<const N: usize> {
    entries: [Option<ActionReaction>; N],
}

impl<const N: usize> Default for LinkTable<N> {
    fn default() -> Self {
        Self { entries: [None; N] }
    }
}

impl<const N: usize> LinkTable<N> {
    /// All links.
    pub fn iter(&self) -> impl Iterator<Item = &ActionReaction> {
        self.entries.iter().flatten()
    }

    /// The links whose acting document is `form` in `folder`: the pages the
    /// City must answer with when that page arrives.
    pub fn reactions_to(&self, folder: u8, form: u8) -> impl Iterator<Item = &ActionReaction> {
        self.iter()
            .filter(move |l| l.action_folder == folder && l.action_form == form)
    }

    /// Number of links.
    pub fn len(&self) -> usize {
        self.iter().count()
    }

    /// `true` if there is no link.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Add a link (an identical link already present is accepted as is).
    pub fn add(&mut self, link: ActionReaction) -> Result<(), Reject> {
        if self.iter().any(|l| *l == link) {
            return Ok(());
        }
        let free = self
            .entries
            .iter_mut()
            .find(|e| e.is_none())
            .ok_or(Reject::TableFull)?;
        *free = Some(link);
        Ok(())
    }

    /// Remove a link (the seed deletes links by emptying a folder; this is
    /// the City application's hook for that). Returns whether it existed.
    pub fn remove(&mut self, link: &ActionReaction) -> bool {
        let mut found = false;
        for e in self.entries.iter_mut() {
            if e.as_ref() == Some(link) {
                *e = None;
                found = true;
            }
        }
        found
    }
}

/// Minimum transmission intervals per envelope (King's Page 10), at most `N`.
#[derive(Debug, Clone)]
pub struct IntervalTable<const N: usize> {
    entries: [Option<MinInterval>; N],
}

impl<const N: usize> Default for IntervalTable<N> {
    fn default() -> Self {
        Self { entries: [None; N] }
    }
}

impl<const N: usize> IntervalTable<N> {
    /// The interval set for `envelope`, if any.
    pub fn get(&self, envelope: Envelope) -> Option<&MinInterval> {
        self.iter().find(|m| m.envelope.envelope == envelope)
    }

    /// All intervals.
    pub fn iter(&self) -> impl Iterator<Item = &MinInterval> {
        self.entries.iter().flatten()
    }

    /// Number of envelopes with an interval.
    pub fn len(&self) -> usize {
        self.iter().count()
    }

    /// `true` if no interval is set.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Set (or replace) the interval of an envelope.
    pub fn set(&mut self, m: MinInterval) -> Result<(), Reject> {
        let env = m.envelope.envelope;
        if let Some(e) = self
            .entries
            .iter_mut()
            .flatten()
            .find(|e| e.envelope.envelope == env)
        {
            *e = m;
            return Ok(());
        }
        let free = self
            .entries
            .iter_mut()
            .find(|e| e.is_none())
            .ok_or(Reject::TableFull)?;
        *free = Some(m);
        Ok(())
    }
}
