//! An element of the page as data.

/// An element: its tag, its class (may be empty), its text, its attributes, its style
/// properties (set one by one, as the page's content security policy allows, never as a
/// `style` attribute) and its children, in order (the text comes before the children).
#[derive(Clone, Debug, PartialEq)]
pub struct Element {
    pub tag: &'static str,
    pub class: &'static str,
    pub text: Option<String>,
    pub attributes: Vec<(&'static str, String)>,
    pub style: Vec<(&'static str, String)>,
    pub children: Vec<Element>,
}

impl Element {
    /// An empty `tag` of `class`.
    pub fn new(tag: &'static str, class: &'static str) -> Self {
        Self {
            tag,
            class,
            text: None,
            attributes: Vec::new(),
            style: Vec::new(),
            children: Vec::new(),
        }
    }

    /// With `text` as its text.
    pub fn text(mut self, text: impl Into<String>) -> Self {
        self.text = Some(text.into());
        self
    }

    /// With the attribute `name` set to `value`.
    pub fn attr(mut self, name: &'static str, value: impl Into<String>) -> Self {
        self.attributes.push((name, value.into()));
        self
    }

    /// With its style's property `name` set to `value`.
    pub fn style(mut self, name: &'static str, value: impl Into<String>) -> Self {
        self.style.push((name, value.into()));
        self
    }

    /// With `children` appended.
    pub fn with(mut self, children: impl IntoIterator<Item = Element>) -> Self {
        self.children.extend(children);
        self
    }

    /// The value of its attribute `name`, if set.
    pub fn get(&self, name: &str) -> Option<&str> {
        (self.attributes.iter())
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.as_str())
    }

    /// Itself and every element under it, depth first.
    pub fn all(&self) -> Vec<&Element> {
        let mut all = vec![self];
        for child in &self.children {
            all.extend(child.all());
        }
        all
    }
}
