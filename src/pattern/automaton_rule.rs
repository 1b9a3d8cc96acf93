//! The transformation rule of the vector cellular automaton (the 1/6-8/5 rule family): two
//! tables f and g of two rows (the mother's activity p = 0 or 1) indexed by the prepigment
//! sum m = x(i−1) + x(i) + x(i+1), giving the daughter's prepigment f(p, m) and activity
//! g(p, m) (eqs 2–4 of the paper).
//!
//! A name "a/b-c/d" gives the number of zeros at the start of f's rows (a for p = 0, b for
//! p = 1) and of g's rows (c, d). Table 1 shows the 1/6-8/5 rule up to m = 13; the expansion
//! that reproduces it entry for entry, and continues it for every m, is
//!
//!   g(p, m) = 0 for m < z, 1 from there on;
//!   f(p, m) = 0 for m < z, then 1 + ⌊m/3⌋ − ⌊z/3⌋,
//!
//! with z the row's number of zeros: the daughter inherits about the mean prepigment of her
//! mother and aunts, one more than the mean when the first non-zero value comes early (an
//! inactive mother producing prepigment), one less when it comes late (an active mother using
//! it). Prepigment counts are capped at [`MAX_COUNT`], so the tables run to m = 3 × MAX_COUNT;
//! a custom table shorter than that keeps its last value for larger sums.

/// The largest prepigment count a cell can hold.
pub const MAX_COUNT: u32 = 255;
/// The largest prepigment sum of three cells.
pub const MAX_SUM: usize = 3 * MAX_COUNT as usize;

/// The tables f and g, each `[row for p = 0, row for p = 1]`, indexed by m up to [`MAX_SUM`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rule {
    pub f: [Vec<u32>; 2],
    pub g: [Vec<u32>; 2],
}

fn zeros(text: &str, name: &str) -> Result<usize, String> {
    text.parse::<usize>()
        .ok()
        .filter(|&z| z <= MAX_SUM)
        .ok_or_else(|| {
            format!("rule '{name}': '{text}' is not a number of zeros from 0 to {MAX_SUM}")
        })
}

impl Rule {
    /// Expands a name "a/b-c/d".
    pub fn named(name: &str) -> Result<Self, String> {
        let shape =
            || format!("rule '{name}' is not of the form a/b-c/d (numbers of zeros, e.g. 1/6-8/5)");
        let (fz, gz) = name.split_once('-').ok_or_else(shape)?;
        let (a, b) = fz.split_once('/').ok_or_else(shape)?;
        let (c, d) = gz.split_once('/').ok_or_else(shape)?;
        let [a, b, c, d] = [a, b, c, d].map(|t| zeros(t.trim(), name));
        let (a, b, c, d) = (a?, b?, c?, d?);
        let f_row = |z: usize| -> Vec<u32> {
            (0..=MAX_SUM)
                .map(|m| {
                    if m < z {
                        0
                    } else {
                        (1 + m / 3 - z / 3).min(MAX_COUNT as usize) as u32
                    }
                })
                .collect()
        };
        let g_row = |z: usize| -> Vec<u32> { (0..=MAX_SUM).map(|m| u32::from(m >= z)).collect() };
        Ok(Self {
            f: [f_row(a), f_row(b)],
            g: [g_row(c), g_row(d)],
        })
    }

    /// Tables given in full (two rows each, of equal length k + 1); shorter than
    /// [`MAX_SUM`] + 1, each row keeps its last value.
    pub fn tables(f: &[Vec<u32>], g: &[Vec<u32>]) -> Result<Self, String> {
        let rows = |t: &[Vec<u32>], name: &str| -> Result<[Vec<u32>; 2], String> {
            let [r0, r1] = t else {
                return Err(format!(
                    "table {name} needs two rows (p = 0 and p = 1), not {}",
                    t.len()
                ));
            };
            if r0.is_empty() || r0.len() != r1.len() {
                return Err(format!(
                    "table {name}'s two rows must be of the same, non-zero length"
                ));
            }
            if r0.len() > MAX_SUM + 1 {
                return Err(format!(
                    "table {name} has {} columns, more than the {} sums that exist",
                    r0.len(),
                    MAX_SUM + 1
                ));
            }
            let extend = |r: &Vec<u32>| {
                let mut r = r.clone();
                let last = *r.last().expect("non-empty");
                r.resize(MAX_SUM + 1, last);
                r
            };
            Ok([extend(r0), extend(r1)])
        };
        let (f, g) = (rows(f, "f")?, rows(g, "g")?);
        if let Some(v) = f.iter().flatten().find(|&&v| v > MAX_COUNT) {
            return Err(format!(
                "table f holds {v}, more prepigment than a cell can have ({MAX_COUNT})"
            ));
        }
        if let Some(v) = g.iter().flatten().find(|&&v| v > 1) {
            return Err(format!("table g holds {v}, but an activity is 0 or 1"));
        }
        Ok(Self { f, g })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_1_is_the_expansion_of_1_6_8_5() {
        let rule = Rule::named("1/6-8/5").unwrap();
        let f0 = [0, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5, 5];
        let f1 = [0, 0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3];
        let g0 = [0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1];
        let g1 = [0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1];
        assert_eq!(rule.f[0][..14], f0);
        assert_eq!(rule.f[1][..14], f1);
        assert_eq!(rule.g[0][..14], g0);
        assert_eq!(rule.g[1][..14], g1);
    }

    #[test]
    fn the_name_counts_the_zeros_of_each_row() {
        for (a, b, c, d) in [(1, 6, 8, 4), (1, 6, 6, 5), (0, 3, 2, 9)] {
            let rule = Rule::named(&format!("{a}/{b}-{c}/{d}")).unwrap();
            let leading = |r: &Vec<u32>| r.iter().take_while(|&&v| v == 0).count();
            assert_eq!([leading(&rule.f[0]), leading(&rule.f[1])], [a, b]);
            assert_eq!([leading(&rule.g[0]), leading(&rule.g[1])], [c, d]);
        }
    }

    #[test]
    fn bad_names_and_tables_get_clear_messages() {
        for bad in ["", "1/6", "1-6-8-5", "1/x-8/5", "1/6-8/5000", "a/b-c/d"] {
            let e = Rule::named(bad).unwrap_err();
            assert!(e.contains("rule"), "{bad}: {e}");
        }
        assert!(
            Rule::tables(&[vec![0, 1]], &[vec![0], vec![1]])
                .unwrap_err()
                .contains("two rows")
        );
        assert!(
            Rule::tables(&[vec![0, 1], vec![0]], &[vec![0], vec![1]])
                .unwrap_err()
                .contains("same")
        );
        assert!(
            Rule::tables(&[vec![0, 1], vec![0, 2]], &[vec![0, 2], vec![0, 1]])
                .unwrap_err()
                .contains("0 or 1")
        );
        assert!(
            Rule::tables(&[vec![0, 999], vec![0, 0]], &[vec![0, 1], vec![0, 1]])
                .unwrap_err()
                .contains("255")
        );
        let custom = Rule::tables(
            &[vec![0, 1, 2], vec![0, 0, 1]],
            &[vec![0, 0, 1], vec![0, 1, 1]],
        )
        .unwrap();
        assert_eq!(custom.f[0][100], 2, "a short table keeps its last value");
    }
}
