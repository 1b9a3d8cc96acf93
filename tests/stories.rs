//! The stories of species/stories/: every one parses, every step opens its link unrepaired
//! and grows; a broken story is refused by name, step and key; the story link opens the step it
//! names, the last for one beyond the end, each with a note.

use seashells_core::generator::Generator;
use seashells_core::share::link;
use seashells_core::stories::{Growth, Story, open, stories, story};
use seashells_core::work::session::{Effect, Session};
use seashells_core::work::status_readout::Say;

#[test]
fn every_story_checks_clean_and_each_step_grows_finite() {
    assert!(stories().len() >= 5, "{} stories", stories().len());
    for s in stories() {
        let errors = s.check();
        assert!(
            errors.is_empty(),
            "{}",
            errors.iter().map(|e| format!("{e}\n")).collect::<String>()
        );
        for (i, step) in s.steps.iter().enumerate() {
            let spec = link::decode(&step.link).spec;
            let mut g =
                Generator::new(&spec).unwrap_or_else(|e| panic!("{} step {}: {e}", s.id, i + 1));
            g.advance(g.rows().min(24));
            let mesh = g.snapshot();
            assert!(
                mesh.vertices
                    .iter()
                    .all(|v| v.position.iter().all(|x| x.is_finite())),
                "{} step {}: a non-finite vertex",
                s.id,
                i + 1
            );
        }
    }
}

/// What the page does on a story's Next link, for every step of every story, as the page's
/// session decides it (`web/app/show.rs` only writes the step's words out): the step shown is
/// the one its link names, counted as the story has it, the shell shown is the step's link,
/// nothing had to be repaired, a step grown whole stands still, and a step that names a
/// parameter map opens it over those numbers.
#[test]
fn the_session_walks_every_story_by_its_next_links_as_the_page_shows_them() {
    for s in stories() {
        let n = s.steps.len();
        let mut session = Session::default();
        let mut fragment = format!("#story={}", s.id);
        for (i, step) in s.steps.iter().enumerate() {
            let at_step = format!("{} step {}", s.id, i + 1);
            session.route(&fragment, false, 0.0);
            let effects = session.take_effects();
            let at = effects
                .iter()
                .find_map(|e| match e {
                    Effect::Story(Some(at)) => Some(at.clone()),
                    _ => None,
                })
                .unwrap_or_else(|| panic!("{at_step}: no step shown"));
            assert_eq!((at.story.id, at.index), (s.id, i), "{at_step}");
            assert_eq!(at.count(), format!("Step {} of {n}", i + 1));
            let said: Vec<&String> = (effects.iter())
                .filter_map(|e| match e {
                    Effect::Say(Say::Show(words)) => Some(words),
                    _ => None,
                })
                .collect();
            assert!(said.is_empty(), "{at_step} needs a repair: {said:?}");
            let (preset, spec) = session.current().expect("a shell shown");
            let asked = link::decode(&step.link);
            assert_eq!(
                link::encode(preset, spec),
                link::encode(asked.preset, &asked.spec),
                "{at_step}: the shell shown is the step's link"
            );
            if step.growth == Growth::Whole {
                assert!(!session.playing(), "{at_step} is shown whole and still");
            }
            let map = effects.iter().find_map(|e| match e {
                Effect::OpenMap(axes) => Some(axes),
                _ => None,
            });
            assert_eq!(map, step.map.as_ref(), "{at_step}: its map");
            match at.next() {
                Some(next) => fragment = format!("#{next}"),
                None => assert_eq!(i + 1, n, "{at_step}: the last has no next"),
            }
        }
    }
}

#[test]
fn the_five_stories_the_issue_names_are_there() {
    for id in ["coiling", "waves", "automaton", "kawaguchi", "murex"] {
        assert!(story(id).is_some(), "missing story {id}");
    }
}

#[test]
fn a_broken_story_is_refused_by_name_step_and_key() {
    let unknown = Story::parse(
        "broken",
        r#"{"title":"t","summary":"s","steps":[],"colour":"red"}"#,
    )
    .expect_err("an unknown field is refused");
    assert_eq!((unknown.story.as_str(), unknown.step), ("broken", None));
    assert!(unknown.message.contains("colour"), "{unknown}");

    let step = |link: &str, map: &str| {
        format!(
            r#"{{"title":"A","summary":"B","steps":[
                {{"title":"fine","link":"v=1&preset=turbinate","text":"x"}},
                {{"title":"bad","link":"{link}","text":"y"{map}}}]}}"#
        )
    };
    let check = |json: String| {
        Story::parse("broken", Box::leak(json.into_boxed_str()))
            .expect("parses")
            .check()
    };
    let errors = check(step("v=1&preset=turbinate&form.spiral.whorls=oops", ""));
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].step, Some(2));
    assert_eq!(errors[0].key, "form.spiral.whorls");
    assert!(
        errors[0]
            .to_string()
            .starts_with("story 'broken', step 2: form.spiral.whorls:"),
        "{}",
        errors[0]
    );

    let errors = check(step("v=1&preset=nautilus", ""));
    assert_eq!(errors[0].key, "preset", "{errors:?}");

    // Raup's coordinates are a swept shell's; Kawaguchi's horn has none.
    let errors = check(step(
        "v=1&preset=kawaguchi-horn",
        r#","map":{"across":"raup.w","down":"raup.t"}"#,
    ));
    assert_eq!(errors.len(), 2, "{errors:?}");
    assert!(
        errors
            .iter()
            .all(|e| (e.step, e.key.as_str()) == (Some(2), "map"))
    );
    assert!(errors[0].message.contains("'raup.w'"), "{}", errors[0]);
    let errors = check(step(
        "v=1&preset=turbinate",
        r#","map":{"across":"raup.w","down":"raup.w"}"#,
    ));
    assert!(errors[0].message.contains("both axes"), "{errors:?}");

    let empty = Story::parse("empty", r#"{"title":"t","summary":"s","steps":[]}"#).unwrap();
    assert_eq!(empty.check()[0].key, "steps");
}

#[test]
fn a_story_link_opens_its_step_and_keeps_its_interface_on_the_next() {
    let s = story("coiling").expect("the coiling story");
    let last = s.steps.len();
    let opened = open("#story=coiling&step=2&ui=controls").unwrap().unwrap();
    assert_eq!(opened.at.index, 1);
    assert!(opened.problems.is_empty(), "{:?}", opened.problems);
    assert_eq!(opened.link, format!("{}&ui=controls", s.steps[1].link));
    assert_eq!(
        opened.at.previous().as_deref(),
        Some("story=coiling&step=1&ui=controls")
    );
    assert_eq!(
        opened.at.next().as_deref(),
        Some("story=coiling&step=3&ui=controls")
    );
    assert_eq!(opened.at.link(), "story=coiling&step=2&ui=controls");

    let first = open("story=coiling").unwrap().unwrap();
    assert_eq!((first.at.index, first.at.previous()), (0, None));

    let beyond = open(&format!("story=coiling&step={}", last + 5))
        .unwrap()
        .unwrap();
    assert_eq!((beyond.at.index, beyond.at.next()), (last - 1, None));
    assert_eq!(beyond.problems[0].key, "step");
    assert!(
        beyond.problems[0].message.contains("opened the last"),
        "{}",
        beyond.problems[0]
    );

    for bad in ["0", "two", "-1"] {
        let opened = open(&format!("story=coiling&step={bad}")).unwrap().unwrap();
        assert_eq!(opened.at.index, 0, "{bad}");
        assert!(
            opened.problems[0].message.contains("opened the first"),
            "{bad}"
        );
    }
    let other = open("story=coiling&form.spiral.whorls=3").unwrap().unwrap();
    assert_eq!(other.problems[0].key, "form.spiral.whorls");

    let unknown = open("story=nautilus").unwrap().expect_err("no such story");
    assert_eq!(unknown.key, "story");
    assert!(unknown.message.contains("'nautilus'") && unknown.message.contains("coiling"));

    assert!(
        open("v=1&preset=turbinate").is_none(),
        "a shell's link names no story"
    );
    assert!(open("").is_none());
}
