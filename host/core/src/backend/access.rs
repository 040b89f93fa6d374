//! What each command reads and writes, and where a barrier must go between commands: one rule for
//! the Vulkan backend's barriers and for the accesses a [`Recording`](crate::frame::Recording)
//! shows a render graph.
//!
//! A kernel's `read` bindings (its [`KernelDesc::read_only`] mask) and sampled images are reads and
//! its other bindings writes;
//! an indirect dispatch reads its arguments; a fill writes; a copy reads its source and writes its
//! destination; a draw reads its storage buffers and its indirect command and writes its target.

use super::{BufferId, ImageRef};
use dof_shaders::KernelDesc;
use std::collections::HashSet;
use std::hash::Hash;

/// A resource a command accesses: a backend buffer, or a caller's image by its raw handle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Resource {
    Buffer(BufferId),
    Image(u64),
}

/// One resource a command reads, or writes (a write may also read).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Access {
    pub resource: Resource,
    pub writes: bool,
}

impl Access {
    pub(crate) fn read(buffer: BufferId) -> Access {
        Access { resource: Resource::Buffer(buffer), writes: false }
    }

    pub(crate) fn write(buffer: BufferId) -> Access {
        Access { resource: Resource::Buffer(buffer), writes: true }
    }
}

/// The accesses of a dispatch of `kernel` bound to `buffers` (its storage buffers, binding order)
/// and `images` (read where it samples them, written where they are storage images), reading its workgroup counts from `indirect_args` where it is
/// indirect.
pub(crate) fn dispatch_accesses(
    kernel: &KernelDesc,
    buffers: &[BufferId],
    images: &[ImageRef],
    indirect_args: Option<BufferId>,
) -> Vec<Access> {
    let buffer_bindings = (0..kernel.bindings).filter(|b| kernel.images & (1 << b) == 0);
    let image_bindings = (0..kernel.bindings).filter(|b| kernel.images & (1 << b) != 0);
    buffers
        .iter()
        .zip(buffer_bindings)
        .map(|(&b, binding)| Access { resource: Resource::Buffer(b), writes: kernel.read_only & (1 << binding) == 0 })
        .chain(images.iter().zip(image_bindings).map(|(image, binding)| Access {
            resource: Resource::Image(image.handle),
            writes: kernel.storage_images & (1 << binding) != 0,
        }))
        .chain(indirect_args.map(Access::read))
        .collect()
}

/// The accesses of a draw reading `buffers` and its indirect command `args` into `target`.
pub(crate) fn draw_accesses(buffers: &[BufferId], args: BufferId, target: BufferId) -> Vec<Access> {
    buffers.iter().chain([&args]).map(|&b| Access::read(b)).chain([Access::write(target)]).collect()
}

/// The accesses of a copy between the image `image` (its raw handle) and `buffer`.
pub(crate) fn copy_accesses(image: u64, buffer: BufferId, into_image: bool) -> [Access; 2] {
    [Access { resource: Resource::Buffer(buffer), writes: !into_image }, Access { resource: Resource::Image(image), writes: into_image }]
}

/// Where barriers go in a sequence of commands: before a command that reads what a command since
/// the last barrier wrote, or writes what one read or wrote, and before the first command.
/// Commands that share nothing, or only read what they share, need none between them. `K` names a
/// resource (a [`Resource`], or a raw handle).
#[derive(Clone, Debug)]
pub struct Hazards<K> {
    /// What the commands since the last barrier read and wrote; `None` before the first command,
    /// which waits for everything before.
    since: Option<(HashSet<K>, HashSet<K>)>,
}

impl<K> Default for Hazards<K> {
    fn default() -> Self {
        Hazards { since: None }
    }
}

impl<K: Hash + Eq + Copy> Hazards<K> {
    /// Takes the next command's accesses (`(resource, writes)`); returns whether a barrier goes
    /// before it.
    pub fn next(&mut self, accessed: &[(K, bool)]) -> bool {
        let barrier = match &self.since {
            None => true,
            Some((read, written)) => accessed.iter().any(|(k, writes)| written.contains(k) || (*writes && read.contains(k))),
        };
        if barrier {
            self.after_barrier();
        }
        if let Some((read, written)) = &mut self.since {
            for &(k, writes) in accessed {
                if writes {
                    written.insert(k)
                } else {
                    read.insert(k)
                };
            }
        }
        barrier
    }

    /// Forgets every access: a barrier covering them all was recorded.
    pub fn after_barrier(&mut self) {
        self.since = Some((HashSet::new(), HashSet::new()));
    }

    /// Starts over: the next command is the first of a command buffer, with a barrier before it.
    pub fn restart(&mut self) {
        self.since = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn barriers_go_only_where_a_command_depends_on_an_earlier_one() {
        let mut h = Hazards::<u32>::default();
        assert!(h.next(&[(1, false), (2, true)]), "the first command waits for everything before");
        assert!(!h.next(&[(1, false), (3, true)]), "reads of a read buffer and a fresh write: no hazard");
        assert!(h.next(&[(2, false)]), "reads what the first wrote");
        assert!(!h.next(&[(4, true)]));
        assert!(h.next(&[(2, true)]), "writes what the last barrier's command read");
        assert!(h.next(&[(2, true)]), "write after write");
        h.restart();
        assert!(h.next(&[(9, false)]));
    }
}
