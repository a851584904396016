#pragma once
// Thesis section 4.4: a candidate is a ball only if, in its square, enough pixels are
// non-green and non-black, and enough of its circle is present as edges (circularity).
#include "core/BallCandidate.h"
#include "core/CarpetColour.h"
#include "core/ColorClass.h"
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnitune {

class Geometry;
class BallModel;

struct ValidationOptions {
    double minNonGreenPct = 85.0;    // %; the ball is never green and fills its square
    // %; rejects black robots (a robot's square is mostly black). Thesis 50; on the optics matrix
    // 30 found 2 points more balls (part-black balls, balls in shade) and no more false positives.
    double minNonBlackPct = 30.0;
    double minCircularityPct = 70.0; // %; a still ball gives ~90, motion blur lowers it
    // %; the circularity a candidate in the clear needs: its square at least clearMinNonBlackPct
    // non-black, so no robot hides it and every usable ray is the ball's own border, and its
    // fitted circle the expected size (clearMaxFitError). Blur and noise cost such a ball a few
    // rays below minCircularityPct (a 10 px ball has 63 rays: 70 % is 45 hits, 60 % is 38). A
    // candidate beside black keeps minCircularityPct: its rays into the robot are left out
    // (ignoreOccludedRays) and the robot's own outline is what its other rays see. At or above
    // minCircularityPct: one threshold for every candidate (the thesis). Optics matrix, 4 frames
    // per cell: 65 % found 29 balls more than 70 (seeds 1-3); 60 % with clearMaxFitError 0.15
    // another 13 (seeds 1-4), no false-positive frame more either time.
    double minCircularityClearPct = 60.0;
    // %; the non-black share that puts a candidate in the clear. 60 rather than 70 found 3 balls
    // more on seeds 1-4 (a ball with a dark panel or a dark shadow under it), no false positive more.
    double clearMinNonBlackPct = 60.0;
    // px; the clear threshold applies to candidates whose expected radius is at least this: a far
    // line junction or line end is as round as a small ball (see lineArms), and a line's V at
    // 7 px or a line end against a robot at 8.6 px passed at 65 % on the optics matrix.
    double clearMinRadiusPx = 9.0;
    // Fraction of the expected radius; a candidate is in the clear only when the circle fit's
    // radius lies this close to the expected one (with circleFit): the balls at 60-69 % fit
    // within 0.06 of it mostly (0.83-1.13 of it at most), while the false positive that passed
    // at 60 % without this (optics matrix seed 1) fit 0.22 small. 1: no such condition.
    double clearMaxFitError = 0.15;
    double radiusTolerance = 0.15;   // fraction of the expected radius searched for an edge
    // px; the search band is never thinner. Segmentation and Canny put a small ball's border up
    // to ~1 px inside the expected radius; at 1.0 a third of 5 px balls failed circularity.
    double minRadiusBandPx = 1.5;
    // px; candidates whose expected radius is smaller are not validated (rejected): below
    // ~4 px a line corner passes all three tests as often as a ball does (measured on
    // simulated tours). Lower it to search farther, at the price of false positives.
    double minRadiusPx = 4.0;
    // A ray counts only when the first edge it meets walking out from the centre lies in the
    // band (a ball's border is its first edge). The thesis counts any edge in the band, which
    // lets line corners and junctions with edges all around a small radius pass.
    bool firstEdgeOnly = true;
    // A ray counts only when carpet (or an unprocessed pixel) lies just beyond its edge: a
    // ball's border opens onto the field, the edges of a line corner lead into more line.
    bool borderIntoCarpet = true;
    // Rays whose border leads into black (a robot in front of or beside the ball) are left
    // out of the circularity, like rays into masked pixels: a ball 10 % behind a robot was
    // found in 55 % of simulated frames without this, 100 % with it. Robots themselves are
    // still rejected by the non-black test.
    bool ignoreOccludedRays = true;
    // %; a candidate is rejected when along more of its rays the colour class of its centre
    // runs on without a break out beyond the circle (to runOnReach expected radii; rays meeting
    // black or masked pixels are not judged). A ball on carpet, or beside a line, has carpet
    // just outside its border; at a line corner or line end the line goes on. Measured on the
    // simulated tours (docs/evaluation.md): balls 0 % (10 % at most for a white ball touching
    // a line), the far line corners that passed every other test 18.5 % and more. 100 turns
    // the test off.
    double maxRunOnPct = 15.0;
    // Expected radii; how far out the centre's colour must run on for a ray to count in the
    // run-on test: past the ball's blurred border (~1 px) but not as far as a nearby line (balls
    // beside a line keep a strip of carpet). 1.5 and 1.75 left far line corners at 11 %, barely
    // above a white ball touching a line (10 %); 1.3 puts them at 18.5 % and more.
    double runOnReach = 1.3;
    // 0..255; in the run-on test an unclassified pixel ends the run of an unclassified centre
    // when it is greyer by more than this (chroma, max - min of B, G, R) and no darker (mean of
    // B, G, R): line paint (needs the frame's colours; 0: off, the class alone). In dim light a
    // coloured ball and a grey line both leave every class, and a ball touching such a line
    // "ran on" along it. Optics matrix seeds 1-4: combined 2576 -> 2595 balls, false-positive
    // frames unchanged (17). "No darker": a symmetric chroma test found 2620 but also ended runs
    // along a leg's darker shading and passed two legs at the rim as balls (19).
    double runOnChromaStep = 20.0;
    // 0..90 (OpenCV's hue, 0-179); in the run-on test an unclassified pixel also ends the run of
    // an unclassified centre when their hues lie this far apart (the shorter way round), both
    // with at least runOnHueMinChroma of chroma (below it noise decides the hue): another
    // object's colour. In dim light a ball lying against a robot's marker band leaves every
    // class, as the band does, and "ran on" along the band. A robot's or a leg's own shading
    // keeps its hue, and still runs on. 0: off. Optics matrix, combined, balls / false-positive
    // frames: seeds 1-4 2732 / 18 -> 2747 / 18, seeds 5-6 1347 / 16 -> 1352 / 16. A step of 12:
    // one false-positive frame more. A chroma floor of 8 found 2753 on seeds 1-4 but passed a
    // leg's blue trousers over a near-grey shoe (chroma 7-9) on seed 1's 2-frame sample.
    double runOnHueStep = 20.0;
    double runOnHueMinChroma = 12.0;  // 0..255, chroma (max - min of B, G, R); see runOnHueStep
    // 0..765 (B + G + R); in the run-on test an unclassified pixel also ends the run of an
    // unclassified centre when their colours differ by more than this, the three channels'
    // absolute differences added, and the pixel is no darker: another object, whatever its hue or
    // chroma. A ball at the carpet's edge lies against the grey hall floor, and one touching a
    // line in shade against its unclassified paint; the hue and chroma steps miss a dark ball on a
    // grey floor. "No darker" keeps a leg running on into its shoe. Optics matrix, 4 frames per
    // cell, seeds 1-8, combined: 5528 -> 5589 balls, false-positive frames 32 -> 32; without "no
    // darker" 5593 / 33 (and one more on the 2-frame matrix: the leg). 0: off.
    double runOnColourStep = 60.0;
    // Fraction of the circle's rays; rays whose whole search band lies on unprocessed pixels
    // (robot body, rods) say nothing about the shape and are left out. With fewer usable rays
    // than this share the circularity is not judged (0 %, so the candidate fails).
    double minUsableRayShare = 0.25;
    // Fraction; of the usable rays and those whose border leads into a robot's black or marker
    // band, at least this share must be usable, else the circularity is not judged. A circle in
    // a robot's black body at the corner of its marker band has nearly every ray leading into
    // black or marker, and passed on the few left: most false positives of the optics matrix on
    // robots. A ball beside or half in front of a robot keeps half its rays. Masked rays (a ball
    // behind a rod) and rays into a line or a foot do not count here: with the line's and
    // foot's rays counted, the quality gate's Auto colours test on a teal carpet lost a ball.
    // 0: off (the usable share of all rays alone). Optics matrix, combined, balls /
    // false-positive frames: seeds 1-4 2748 / 18 -> 2747 / 15, seeds 5-6 1355 / 12 -> 1355 / 7,
    // seeds 7-8 1364 / 12 -> 1364 / 9.
    double minUnoccludedRayShare = 0.35;
    // px; how far beyond a ray's edge its colour is read for borderIntoCarpet and
    // ignoreOccludedRays: past the edge's own blurred pixel, still next to the ball.
    double beyondEdgePx = 1.5;
    // A ray that walks into masked or out-of-mirror pixels before it meets the ball's border is
    // left out of the circularity, like a ray whose band is all masked: a ball half behind a rod
    // is judged on its visible half. Off: such a ray counts as a miss (the earlier rule).
    bool maskedRaysUnknown = true;

    // Circularity by a circle fit: each ray's first border into carpet within a wide range
    // (expected radius + fitMaxRadiusErrorPx) is a point; a circle is fitted to the points
    // (robust to a few strays) and the circularity is the share of the usable rays whose point
    // lies within the band of the *fitted* circle. The candidate also fails circularity when
    // the fitted radius or centre is more than max(fitMaxRadiusErrorPx, fitMaxRadiusError x
    // expected radius) off. A ball the radius model misjudges by 2-3 px, or a candidate 2 px off
    // its ball, passes; a straight edge or corner has no circle through its border points.
    // Off: the thesis' fixed band around the expected radius.
    bool circleFit = true;
    double fitMaxRadiusErrorPx = 3.0;  // px
    double fitMaxRadiusError = 0.25;   // fraction of the expected radius
    // The fitted circle is judged against the expected one only where the ball is seen: it passes
    // when, along every usable ray (not masked, occluded or out of the mirror), its border lies
    // within the same allowance of the expected border. A ball half behind our body or a rod
    // shows one arc; the Hough's centre and the fit both slide along that arc's axis when the
    // radius model is 2 px off, so centre and radius are off together while the visible border
    // fits. For a ball seen whole this is no looser than the centre and radius tests (the largest
    // border gap is the centre's offset plus the radius' error), so only partly hidden balls gain.
    bool fitVisibleBorder = true;
    double fitVisibleMinShare = 0.5;  // of the rays usable for it to apply (a line crossing a rod shows ~0.3)
    // A ray outwards (within the half-angle whose cosine is hallOutwardCos of the direction away
    // from the mirror centre) that found no border and runs out over the hall floor, reaching the
    // mirror's rim within hallReachRadii expected radii past its band and meeting no carpet
    // (core/HallRay.h), is judged by colour: its border is where the pixels stop differing from
    // the floor's colour by hallColourStep. A far ball at the carpet's edge lies half over the
    // floor, which the binary image does not part from it. Needs the frame's colours. Off: such a
    // ray is a miss (the binary image alone).
    bool hallRaysByColour = true;
    double hallColourStep = 40.0;  // |dB| + |dG| + |dR|, 0..765
    double hallReachRadii = 4.0;   // expected radii past the band
    double hallOutwardCos = 0.3;   // cosine of the half-angle
    // A ray's border point is the edge pixel it met, not the point at the ray's step where it
    // met it (up to ~0.7 px off: the band of a 3-6 px ball is 1.5 px). Off by default: on the
    // optics matrix it found 1.3 points more balls (combined), but it also makes a blurred round
    // floor reflection round enough to pass (tests/core_validation realFrameFalsePositives).
    bool borderAtPixel = false;

    // Green pixels count as carpet (non-green test, borders into carpet) only when their hue and
    // saturation match the carpet measured around the candidate (CarpetColour): green panels of
    // a ball, or its shaded green side, are then ball. Needs the frame's colours (validateCandidate
    // with a FrameColour); without them, or with too little carpet around, every green is carpet.
    bool carpetByColour = true;
    CarpetTolerance carpetTolerance;
    // The non-green test's square counts a carpet-coloured pixel darker than the carpet around
    // the candidate by more than this (and than carpetTolerance.sigmas of its spread) as ball:
    // a ball's shaded side and the green panels at its silhouette are darker than the carpet
    // beside it. Only in a square of which greenPanelMinOwnPct is neither carpet nor black (a
    // ball's own colours), so that a shadow on the carpet or a robot's shaded edge stays green;
    // the borders never judge brightness this way (a contact shadow beside the ball is carpet
    // there). 0: off (the thesis: colour alone).
    double squareShadeTolerance = 20.0;  // V, 0..255
    // The ring the carpet's colour is measured in, around the candidate: from
    // carpetRingInner x radius + carpetRingMarginPx to carpetRingOuter x radius + 2 x
    // carpetRingMarginPx. Past the ball's blurred border and its contact shadow, before the next
    // object; the margin keeps a small ball's ring a few pixels wide.
    double carpetRingInner = 1.5;     // expected radii
    double carpetRingOuter = 2.5;     // expected radii
    double carpetRingMarginPx = 1.0;  // px
    // px; how wide the blend of ball and carpet colours at a border may be (7 px motion blur,
    // optics): a ray's edge still leads into carpet when the carpet's own green starts within
    // this many pixels past beyondEdgePx.
    double borderBlendPx = 3.0;

    // The non-black test counts a black-class pixel as black only when it is also darker than
    // localBlackVRatio x the mean V of the carpet measured around the candidate (the ring above).
    // The colour table's black is relative to the whole frame's carpet: in a vignetted corner or a
    // dim half of an unevenly lit hall a ball's shaded side falls below it. Needs the frame's
    // colours; without them, or with too little carpet around, the colour class alone decides.
    bool blackByLocalCarpet = true;
    double localBlackVRatio = 0.45;  // fraction of the local carpet's mean V

    // The mirror rim (geometry.outer_radius): a candidate whose expected circle reaches farther
    // out than outer_radius - rimMarginPx is refused (OutsideArea). The ring ends there, so such
    // a circle is judged on its inner part alone, and on the optics matrix the cut-off ends of
    // lines, robot markers and blurred rim pixels passed that way: most false positives sat
    // there, against fewer balls found there (docs/evaluation.md). Off (the thesis): every
    // candidate whose centre is processed is judged.
    bool refuseAtRim = true;
    double rimMarginPx = 1.0;  // px; negative lets a circle reach past the outer radius

    // The ball's colour class when the team knows it, by name ("none": no hint). When at least
    // ballHintMinPct of the square's processed pixels have that class, the colour tests (non-green,
    // non-black) are passed: the ball's own colour shows it is neither carpet nor robot. The shape
    // tests still apply. Never required.
    std::string ballHint = "none";
    double ballHintMinPct = 15.0;  // %

    // A ray that leaves the candidate's colours into a field line going on past lineContactReach
    // expected radii is left out of the circularity, like a ray into a robot (core/LineContact.h):
    // a ball touching a line is judged on the rays that open onto carpet. Off (the thesis): such
    // a ray finds no border (ball and line are one blob) and counts as a miss.
    // Only rays that cross the candidate's colours alone from the centre out to
    // lineContactMinEntry expected radii, and whose line then goes on to lineContactReach.
    bool lineRaysUnknown = true;
    double lineContactMinEntry = 0.5;  // expected radii
    double lineContactReach = 1.5;     // expected radii
    // When the candidate's centre has a ball class (the team's ball colour), a ray that crosses
    // that class alone (or black, its shaded side) out to lineContactMinEntry and then runs into
    // an object that is neither carpet nor line, going on to lineContactReach, is left out of the
    // circularity too (core/ForeignContact.h): a ball at a person's feet or a robot's grey side.
    // Off (the thesis): such a ray finds no border and counts as a miss.
    bool foreignRaysUnknown = true;
    // A ray whose border leads into a team-marker class (a robot's cyan or magenta band) is left
    // out of the circularity like a ray into black (ignoreOccludedRays): the marker is part of a
    // robot hiding the ball. Off (the thesis): such a ray counts as a miss.
    bool markerRaysUnknown = true;
    // The circularity and run-on tests look for the ellipse the ball model's squash gives
    // (ball.squash_c0..c2: radial over tangential semi-axis, the radial axis towards the mirror
    // centre) instead of a circle: a spherical mirror shows a ball at 1-2 m with a ratio of
    // ~0.7, whose border leaves a circle's band over a third of its rays. Off (the thesis): a
    // circle of the expected radius.
    bool radialSquash = true;
    // px; smaller expected radii keep the circle: their squash lies inside the band
    // (minRadiusBandPx) anyway, and the ellipse's longer tangential reach met clutter at the rim.
    // Optics matrix, 2 frames per ball cell (446 balls, 512 frames; specific / combined balls
    // found, false-positive frames): circle 237 / 240, 7 / 10; ellipse from 0 px 253 / 254, 9 / 10;
    // from 6 px 251 / 252, 9 / 12; from 7.5 px 251 / 252, 7 / 10; from 9 px 249 / 250, 7 / 10.
    double squashMinRadiusPx = 7.5;
    // A carpet-green pixel inside the candidate's expected circle counts as ball, not carpet (non-
    // green test, borders into carpet), when it lies on a panel enclosed by the ball's white
    // (core/GreenPanelTest.h): the green panels of a green-and-white ball have the carpet's hue and
    // saturation, so colour alone (carpetByColour) calls them carpet. Off (the thesis): every
    // carpet-green pixel is carpet.
    bool greenPanels = true;
    // px; the walks from a green pixel stop this far inside the expected circle: the border's own
    // pixels blend ball and carpet, and a radius model 1-2 px off would reach carpet beyond. 2 px
    // stopped short of a panel's thin white rim near the silhouette: 1 found, on the optics matrix
    // (4 frames per cell, seeds 1-4, span 1.5), combined 2545 -> 2560 balls, specific 2504 -> 2516,
    // OpenCV 1770 -> 1785, false-positive frames 17 -> 17, 15 -> 15 and 5 -> 6 of 3840.
    double greenPanelMarginPx = 1.0;
    // Of the 8 compass directions; a green pixel that meets the ball's white before the circle in
    // at least this many also counts as a panel. One at the silhouette has white inwards and on
    // both sides (5 or more); carpet between two crossing lines has it in 5, hence 6. 0: only the
    // walk outwards decides.
    int greenPanelMinDirections = 6;
    // %; the square's non-green share by colour alone (the white panels) from which its green
    // panels count in the non-green test: a green-and-white ball shows ~55 %.
    double greenPanelMinOwnPct = 45.0;
    // Prefilter refusals on the non-green test whose square is at least recentreMinNonGreenPct
    // non-green by class are moved to the centroid of the pixels around them not of the carpet's
    // colour and validated there (core/RefusalRecentre.h), up to recentreRefused per frame,
    // strongest first; 0: they stay refused. One that passes validation there replaces the
    // refusal only when validation's non-green share is recentreMinPanelPct above the class
    // share: green panels (or greens not the carpet's) of its own, which a line corner lacks.
    // 12: with three maxima per area, more refusals are listed and 8 left a near green-and-white
    // ball's own unmoved (optics matrix seeds 1-4: +12 balls, no false positive more).
    int recentreRefused = 12;
    double recentreMinNonGreenPct = 45.0;
    double recentreMinPanelPct = 15.0;
    // px; nor for smaller expected radii: in the far ring, a line's bend or its end at a rod,
    // centred by the move, passes every test (optics matrix seed 2: two false-positive frames).
    double recentreMinRadiusPx = 8.0;
    // With circleFit, candidates refused on circularity whose border fits a circle are moved to
    // the fitted centre and validated there (core/FitRecentre.h), up to refitRecentre per frame
    // in list order; 0: they stay refused. A Hough maximum a few pixels off the ball's centre (a
    // rod or the panels pull the votes) was refused as "circle off model" though its fit was the
    // ball. Optics matrix, combined, balls / false-positive frames: seeds 1-4 2747 / 15 ->
    // 2771 / 16, seeds 5-6 1355 / 7 -> 1369 / 9, seeds 7-8 1364 / 9 -> 1380 / 11; 8 per frame
    // finds the same. Only the "circle off model" refusals (circularity passed): 2753 / 15,
    // 1359 / 8.
    int refitRecentre = 4;
    // px; nor when the expected radius at the fitted centre is smaller: far out in dim light, a
    // robot's marker patch or a pale blob between lines (expected 5.4-6.1 px) fitted a circle and
    // passed there. Combined: seeds 1-4 2771 / 16 -> 2764 / 16, seeds 5-6 1369 / 9 -> 1369 / 8,
    // seeds 7-8 1380 / 11 -> 1377 / 9; 8 px 2756 / 16, 1365 / 8.
    double refitMinRadiusPx = 6.5;

    // With refuseAtRim, a candidate whose expected circle reaches up to rimMaxOverhangPx past
    // outer_radius - rimMarginPx is judged instead of refused when its inward side is closed
    // (core/RimTest.h): at least rimMinClosedPct of its inward rays (within the half-angle whose
    // cosine is rimInwardCos of the direction to the mirror centre) meet the carpet within
    // rimBandPx of the expected radius. A far ball on the carpet passes; a robot marker (the
    // robot's dark body inwards) and a line end (line inwards) do not. Off: every such circle
    // is refused.
    bool rimTest = true;
    double rimMaxOverhangPx = 3.5;  // px
    double rimMinClosedPct = 80.0;  // %
    double rimBandPx = 1.5;         // px
    double rimInwardCos = 0.3;      // cosine of the half-angle
    // Fractions of the ball's expected width along its arc (the squashed ellipse's tangential
    // axis); the candidate's non-field run along the arc through its centre (core/RimTest.h) must
    // lie between them. Optics matrix: rim balls 0.63-1.17, robot markers and line ends cut by the
    // rim 0.57-0.83 (narrower than a ball there), a line along the rim 4.5.
    double rimMinWidth = 0.78;
    double rimMaxWidth = 1.4;
    // px; the arc run ends at carpet only where the arc stays field this much further: a speck
    // of carpet noise in the dim hall floor at the rim ended it and let the floor pass as a ball
    // of the right width. 0: at the first field pixel.
    double rimArcCarpetPx = 1.0;
    // px; rim_min_width is met by the widest of the arc runs through the points up to this far
    // radially in and out of the centre (rim_max_width still reads the arc through the centre):
    // a far ball's centre found 1-2 px off its own crosses the squashed ball off its widest chord,
    // and blur takes the rest. 0: the arc through the centre alone.
    double rimArcOffsetPx = 1.0;
    // A way of the arc run that stops at a masked pixel (a support rod) counts as long as the
    // other way: a far ball at the rim half behind a rod is not a narrow marker. Optics matrix
    // seeds 1-6, combined: 4099 -> 4103 balls, false-positive frames 30 either way. Off: the
    // masked way ends the run.
    bool rimArcMaskedMirrors = true;
    // The inward closure skips field pixels more than rimBandPx inside the border (a green panel
    // of the ball, its shadow's noise): the first field pixel from there on decides. Off: the
    // first field pixel on the ray. Optics matrix seeds 1-4 with both: combined 2595 -> 2627
    // balls, false-positive frames 17 -> 15; skipping alone passed two floor patches (19).
    bool rimSkipInnerField = true;
    // px; a candidate that passes the rim test is validated from this expected radius on (instead
    // of minRadiusPx): the closed inward side is what a line corner of that size lacks.
    double rimMinRadiusPx = 3.5;
    // Levels (|dB| + |dG| + |dR|); a candidate at the rim passes the rim test only when its inside
    // differs from its surroundings off the carpet by at least this (core/SurroundContrast.h): in
    // dim, noisy light a patch of the hall floor at the rim is speckled with "green" and passes
    // the shape. Needs the frame's colours; 0: off.
    double rimMinContrast = 20.0;
    // A candidate that passed every test is rejected (LineJunction) when field lines leave it like
    // spokes (core/LineArms.h): two arms at less than lineArmsMaxAngleDeg, or three or more. The
    // optics matrix's false positives were junctions of the far lines near the horizon, round
    // blobs of a far ball's size; a ball lying on a line has its two arms opposite. Off (the
    // thesis): no such test.
    bool lineArms = true;
    double lineArmsReach = 2.25;        // expected radii; an arm runs from the circle out to here
    double lineArmsLateralPx = 0.5;     // px; beside the ray a line pixel still counts (bent lines); 1 took a
                                        // line beside a 5 px ball for two arms
    double lineArmsMaxAngleDeg = 150.0; // degrees; two arms farther apart are one line through
    // Pale pixels count as line for the arms (core/PaleLine.h): saturation at most
    // paleLineMaxSaturation and V at least paleLineMinValueRatio x the carpet's V around the
    // candidate (or paleLineValueCap). In dim and uneven light the far lines leave the line
    // class; their junctions then had no arms. Needs the frame's colours; off: the line class alone.
    bool lineArmsPale = true;
    int paleLineMaxSaturation = 90;      // 0..255
    double paleLineMinValueRatio = 1.4;  // x the carpet's mean V
    // 0..255; a pale pixel this bright is bright enough whatever the carpet's V. In bright light
    // the carpet's V passes 182, 1.4 x it lies past the sensor's 255, and no line pixel was pale:
    // a clipped spot on a line near the rim passed as a far ball (optics matrix seeds 5-6, bright
    // 480x480: 4 of 16 false-positive frames; as many balls found on seeds 1-6). 0: the ratio alone.
    double paleLineValueCap = 250.0;
    // x the carpet's mean V; a pale pixel of the carpet's own class counts as line too when at
    // least this bright and not of the carpet's colour (carpetTolerance). In dim light a far line
    // is barely brighter than the carpet (seed 6, dim, cyan-green: green 60-70 against 46-57) and
    // both pixel formats put it in the carpet's class, so a junction kept only the arms its noisy
    // pixels happened to show. 0: the carpet's class is never line.
    double paleLineCarpetValueRatio = 1.15;
    // px; larger candidates are not judged: a junction looks round only at a far ball's size,
    // and a near ball's border meets lines at many angles (balls at 10-18 px were lost).
    double lineArmsMaxRadiusPx = 8.0;
    // %; a candidate with one line arm is rejected too when this share of its inside (within
    // lineBlobDisc expected radii) is line colour (core/LineShare.h): a line's end or a narrow V
    // whose arms merged. Balls of the optics matrix at 5-8 px showed at most 48 %, the false
    // positives there 47-80 % (57 until two far line ends at 56 % passed, seeds 1-4). 100 turns
    // it off; a white ball touching a far line is lost to it.
    double lineBlobMinPct = 55.0;
    double lineBlobDisc = 0.8;  // expected radii; inside the blurred border
    // %; a candidate with no line arm at all is rejected (LineBlob) when this share of the same
    // disc is line colour and its line runs on out of sight within lineBlobCutReach: a line's end
    // against the rim, a rod or our body, where its arm ended. Such blobs made most of the optics
    // matrix's false positives (66-100 % line); no ball there showed more than 48 %. 100 turns it
    // off.
    double lineBlobArmlessMinPct = 65.0;
    // expected radii; the disc around the centre that must reach masked or outside pixels. 0
    // judges every armless blob: the penalty spot too, and a plain white ball in the open.
    double lineBlobCutReach = 1.5;
    // px; the cut-blob test (lineBlobArmlessMinPct) also judges candidates larger than
    // lineArmsMaxRadiusPx, up to this expected radius, as armless: a penalty spot or a line's end
    // half behind a support rod at 8-15 px made most of the rods cells' false positives. At or
    // below lineArmsMaxRadiusPx: only the far candidates are judged (the earlier rule).
    double lineBlobCutMaxRadiusPx = 40.0;
    // %; not when more than this share of the line-share disc shows a ball's panels (black, ball
    // or marker classes), which no line has: a white ball behind a rod keeps its dark panels.
    double lineBlobArmlessMaxPanelPct = 3.0;
};

// How far a fitted circle's radius and centre may be off the expected ones (circle_fit):
// max(fit_max_radius_error_px, fit_max_radius_error x the expected radius).
double fitAllowance(double expectedRadiusPx, const ValidationOptions& options);

// The circularity % a scored candidate needs: minCircularityClearPct when it is in the clear (its
// square clearMinNonBlackPct non-black or more, its expected radius clearMinRadiusPx or more) and
// that is the lower one, else minCircularityPct.
double requiredCircularityPct(const BallCandidate& candidate, const ValidationOptions& options);

// Whether a circle at (x, y), `distancePx` from the mirror centre, passes validation's rim
// judgement (refuse_at_rim, rim_test, rim_min_contrast): true when it does not reach the rim, or
// when it does and its width, its inward side and its colour show a ball on the carpet's edge.
// `ballSquash`: the ball model's squash there; `colour` (optional) for rim_min_contrast.
bool rimCutBallPasses(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double distancePx, double expectedRadiusPx, double ballSquash, const ValidationOptions& options,
                      const FrameColour* colour);

// Scores one candidate and sets its `rejected` field (first failing test: too small, then the
// thesis order non-green, non-black, circularity, then our run-on test). `classes` holds colour
// class ids, `edges` the edge image, `colour` (optional) the frame's colours for carpetByColour,
// `roles` what the ids are: "green" is every field class, "black" every black class.
// `stopAtColour`: when the square's colour tests fail, the shape is not measured, and a candidate
// already rejected (outside the area, too large) is not scored at all (the scores stay 0 and say
// so in squareMeasured / shapeMeasured; the verdict is the same): for callers that drop or do
// not explain what is rejected (the recentre, the robot).
void validateCandidate(BallCandidate& candidate, const cv::Mat& classes, const cv::Mat& edges,
                       const Geometry& geometry, const BallModel& ball, const ValidationOptions& options,
                       const FrameColour* colour = nullptr, const ColourRoles& roles = defaultColourRoles(),
                       bool stopAtColour = false);

// The carpet's colour in the ring around a circle of `radius` at (x, y) (carpet_ring_*).
CarpetColour carpetRingAround(const FrameColour& colour, const cv::Mat& classes, const Geometry& geometry,
                              const ColourRoles& roles, int x, int y, double radius, const ValidationOptions& options);

// Validation's non-black share (%) of the processed pixels in the square of odd side `squareSide`
// at (x, y), as scoreCircle counts it: with black_by_local_carpet (and `colour`), a black-class pixel
// is black only when darker than local_black_v_ratio x the carpet around a circle of `radius`.
// For the candidate prefilter, which must not refuse what validation would pass.
double nonBlackPctAt(int x, int y, double radius, int squareSide, const cv::Mat& classes, const Geometry& geometry,
                     const ValidationOptions& options, const FrameColour* colour, const ColourRoles& roles);

// The scores alone, for a circle at (x, y) of the given radius and square side. `squash`: the
// ball's radial over tangential semi-axis there (1: a circle; used when options.radialSquash).
ValidationScores scoreCircle(int x, int y, double radius, int squareSide, const cv::Mat& classes,
                             const cv::Mat& edges, const Geometry& geometry, const ValidationOptions& options,
                             const FrameColour* colour = nullptr, const ColourRoles& roles = defaultColourRoles(),
                             double squash = 1.0, bool stopAtColour = false);

}  // namespace omnitune
