//! Sorting EXR channels into layers: `layer.channel` names, the roles R, G, B, A and depth, and the
//! natural order of layer names.

use std::cmp::Ordering;

/// What a channel holds, from the part of its name after the last `.`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Role {
    R,
    G,
    B,
    A,
    Depth,
}

/// The role of a channel suffix and its rank among the names for that role (lower is preferred:
/// the canonical OpenEXR name first). `R`, `G`, `B`, `A` and `Z` in either case; depth also as
/// `depth` in any case.
pub(crate) fn role(suffix: &str) -> Option<(Role, u8)> {
    let canonical = |s: &str, role| {
        if suffix == s {
            Some((role, 0))
        } else if suffix.eq_ignore_ascii_case(s) {
            Some((role, 1))
        } else {
            None
        }
    };
    canonical("R", Role::R)
        .or_else(|| canonical("G", Role::G))
        .or_else(|| canonical("B", Role::B))
        .or_else(|| canonical("A", Role::A))
        .or_else(|| canonical("Z", Role::Depth))
        .or_else(|| match suffix {
            "depth" => Some((Role::Depth, 2)),
            s if s.eq_ignore_ascii_case("depth") => Some((Role::Depth, 3)),
            _ => None,
        })
}

/// Splits a full channel name into (layer, channel) at the last `.`: `"layer0.R"` → `("layer0",
/// "R")`, `"a.b.Z"` → `("a.b", "Z")`, `"R"` → `("", "R")`.
pub(crate) fn split_name(full: &str) -> (&str, &str) {
    match full.rfind('.') {
        Some(i) => (&full[..i], &full[i + 1..]),
        None => ("", full),
    }
}

/// Whether the depth-only group `depth` holds the depth of the colour group `colour`, as tools
/// write a colour image and its depth in separate layers. Both must share the parent (the name
/// before the last `.`), and (any letter case):
///
/// - Blender: `<P>.Combined` with `<P>.Depth` (`RenderLayer.Combined.R` and
///   `RenderLayer.Depth.Z`, `ViewLayer.Combined.R` and `ViewLayer.Depth.Z`);
/// - Nuke: its main layer `rgba` (or the unnamed root layer) with `depth` (`rgba.R` or `R` and
///   `depth.Z`, also as parts `rgba` and `depth` of a multi-part file).
///
/// Other colour layers (Blender's `DiffCol`, `Emit`, ..., cryptomattes) are passes, not the image.
pub(crate) fn is_depth_sibling(colour: &str, depth: &str) -> bool {
    let (colour_parent, colour_leaf) = split_name(colour);
    let (depth_parent, depth_leaf) = split_name(depth);
    if colour_parent != depth_parent {
        return false;
    }
    let blender = colour_leaf.eq_ignore_ascii_case("combined") && depth_leaf.eq_ignore_ascii_case("depth");
    let nuke_main = colour_leaf.is_empty() || colour_leaf.eq_ignore_ascii_case("rgba");
    let nuke = nuke_main && depth_leaf.eq_ignore_ascii_case("depth");
    blender || nuke
}

/// One group of channels sharing a layer name, with the channel chosen for each role (indices into
/// the caller's channel list) and the others.
#[derive(Clone, Debug, Default)]
pub(crate) struct Group {
    pub name: String,
    pub r: Option<usize>,
    pub g: Option<usize>,
    pub b: Option<usize>,
    pub a: Option<usize>,
    pub depth: Option<usize>,
    /// Channels of the group without a role, or losing to a preferred name for their role.
    pub others: Vec<usize>,
}

impl Group {
    pub fn has_color(&self) -> bool {
        self.r.is_some() || self.g.is_some() || self.b.is_some()
    }
    pub fn has_rgb(&self) -> bool {
        self.r.is_some() && self.g.is_some() && self.b.is_some()
    }
    pub fn is_complete(&self) -> bool {
        self.has_rgb() && self.depth.is_some()
    }
    pub fn missing_colors(&self) -> Vec<&'static str> {
        [(self.r, "R"), (self.g, "G"), (self.b, "B")].into_iter().filter(|(c, _)| c.is_none()).map(|(_, n)| n).collect()
    }
    /// Depth but no colour channel: a depth pass such as Blender's `<P>.Depth.Z` or Nuke's `depth.Z`.
    pub fn is_depth_only(&self) -> bool {
        self.depth.is_some() && !self.has_color()
    }
    /// Every channel index of the group that is used for a role (the others are not).
    pub fn used(&self) -> impl Iterator<Item = usize> + '_ {
        [self.r, self.g, self.b, self.a, self.depth].into_iter().flatten()
    }
}

/// Groups channels (given by full name, in any order) by layer name, in [`natural_cmp`] order of
/// the layer names (the unnamed root group `""` first).
pub(crate) fn group_channels(names: &[String]) -> Vec<Group> {
    let mut order: Vec<usize> = (0..names.len()).collect();
    order.sort_by(|&i, &j| names[i].cmp(&names[j]));
    let mut groups: Vec<Group> = Vec::new();
    // Best rank seen per role, per group, parallel to `groups`.
    let mut ranks: Vec<[u8; 5]> = Vec::new();
    for i in order {
        let (layer, channel) = split_name(&names[i]);
        let g = match groups.iter().position(|g| g.name == layer) {
            Some(g) => g,
            None => {
                groups.push(Group { name: layer.to_string(), ..Default::default() });
                ranks.push([u8::MAX; 5]);
                groups.len() - 1
            }
        };
        let group = &mut groups[g];
        let Some((role, rank)) = role(channel) else {
            group.others.push(i);
            continue;
        };
        let (slot, best) = match role {
            Role::R => (&mut group.r, &mut ranks[g][0]),
            Role::G => (&mut group.g, &mut ranks[g][1]),
            Role::B => (&mut group.b, &mut ranks[g][2]),
            Role::A => (&mut group.a, &mut ranks[g][3]),
            Role::Depth => (&mut group.depth, &mut ranks[g][4]),
        };
        if rank < *best {
            if let Some(previous) = slot.replace(i) {
                group.others.push(previous);
            }
            *best = rank;
        } else {
            group.others.push(i);
        }
    }
    groups.sort_by(|a, b| natural_cmp(&a.name, &b.name));
    groups
}

/// "Natural" order of layer names: runs of digits compare as numbers, so `layer2 < layer10`; other
/// runs compare bytewise; names equal under this order (`layer01`, `layer1`) fall back to bytewise.
pub fn natural_cmp(a: &str, b: &str) -> Ordering {
    let (mut x, mut y) = (a.as_bytes(), b.as_bytes());
    loop {
        match (x.first(), y.first()) {
            (None, None) => return a.cmp(b),
            (None, Some(_)) => return Ordering::Less,
            (Some(_), None) => return Ordering::Greater,
            (Some(p), Some(q)) if p.is_ascii_digit() && q.is_ascii_digit() => {
                let dx = x.iter().take_while(|c| c.is_ascii_digit()).count();
                let dy = y.iter().take_while(|c| c.is_ascii_digit()).count();
                let strip = |d: &[u8]| {
                    let z = d.iter().take_while(|&&c| c == b'0').count();
                    d[z..].to_vec()
                };
                let (nx, ny) = (strip(&x[..dx]), strip(&y[..dy]));
                let ord = nx.len().cmp(&ny.len()).then_with(|| nx.cmp(&ny));
                if ord != Ordering::Equal {
                    return ord;
                }
                x = &x[dx..];
                y = &y[dy..];
            }
            (Some(p), Some(q)) => {
                if p != q {
                    return p.cmp(q);
                }
                x = &x[1..];
                y = &y[1..];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn natural_order() {
        let mut names = vec!["layer10", "layer2", "layer1", "back", "layer01", ""];
        names.sort_by(|a, b| natural_cmp(a, b));
        assert_eq!(names, ["", "back", "layer01", "layer1", "layer2", "layer10"]);
    }

    #[test]
    fn groups_and_roles() {
        let names: Vec<String> =
            ["R", "G", "B", "depth", "Z", "l10.R", "l2.z", "l2.r", "N.X", "coc"].iter().map(|s| s.to_string()).collect();
        let groups = group_channels(&names);
        assert_eq!(groups.iter().map(|g| g.name.as_str()).collect::<Vec<_>>(), ["", "N", "l2", "l10"]);
        assert_eq!(groups[0].depth, Some(4), "Z is preferred over depth");
        assert!(groups[0].others.contains(&3) && groups[0].others.contains(&9));
        assert!(groups[0].is_complete());
        assert!(!groups[1].has_color());
        assert_eq!(groups[2].r, Some(7));
        assert_eq!(groups[2].depth, Some(6));
        assert_eq!(groups[2].missing_colors(), ["G", "B"]);
    }

    #[test]
    fn depth_siblings() {
        for (colour, depth) in [
            ("RenderLayer.Combined", "RenderLayer.Depth"),
            ("ViewLayer.Combined", "ViewLayer.Depth"),
            ("My Layer.combined", "My Layer.depth"),
            ("rgba", "depth"),
            ("", "depth"),
            ("", "Depth"),
        ] {
            assert!(is_depth_sibling(colour, depth), "{colour} / {depth}");
        }
        for (colour, depth) in [
            ("ViewLayer.Combined", "Other.Depth"),
            ("ViewLayer.DiffCol", "ViewLayer.Depth"),
            ("ViewLayer.Combined", "ViewLayer.Mist"),
            ("rgba", "ViewLayer.Depth"),
            ("diffuse", "depth"),
            ("Combined", "ViewLayer.Depth"),
        ] {
            assert!(!is_depth_sibling(colour, depth), "{colour} / {depth}");
        }
    }
}
