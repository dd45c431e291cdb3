// boreas: remakes tests/data/arbaro_figures.csv, the figures test_arbaro_figures.cpp compares
// boreas's trees with, from Arbaro 1.9.9 itself (Wolfram Diestel's Java Weber-Penn generator;
// not a Debian package and not part of the build: run by hand where its source is present).
//
//   javac -d classes $(find ARBARO/src -name '*.java') tests/tools/ArbaroFigures.java
//   java -cp classes net.sourceforge.arbaro.tree.ArbaroFigures SEEDS file.xml... > figures.csv
//   (add --per-seed before SEEDS for one row per tree instead of the means)
//
// For each species file, seeds 1..SEEDS: per level the drawn length (each stem's segments
// times its segment length, split clones included) and the stems (clones included); the
// height (the highest segment end); the crown width (the mean of the segment ends' extents
// along the two horizontal axes); the leaves. Rows: the mean and the seed standard deviation
// of each over the seeds whose tree grew (Arbaro grows nothing for a negative size draw,
// shave-grass's Scale 0.5 +- 0.7; "seeds" counts the trees grown). It sits in Arbaro's tree
// package to read its stems' segments.
package net.sourceforge.arbaro.tree;

import java.io.FileInputStream;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import net.sourceforge.arbaro.export.Console;
import net.sourceforge.arbaro.export.Progress;
import net.sourceforge.arbaro.params.Params;
import net.sourceforge.arbaro.transformation.Vector;

public class ArbaroFigures {
  static final String[] NAMES = {"height", "width", "leaves", "length0", "length1", "length2",
      "length3", "stems0", "stems1", "stems2", "stems3"};
  double[] f = new double[NAMES.length];  // in the order of NAMES
  double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE;
  double minY = Double.MAX_VALUE, maxY = -Double.MAX_VALUE, maxZ = -Double.MAX_VALUE;
  boolean grown = false;

  void point(Vector p) {
    minX = Math.min(minX, p.getX()); maxX = Math.max(maxX, p.getX());
    minY = Math.min(minY, p.getY()); maxY = Math.max(maxY, p.getY());
    maxZ = Math.max(maxZ, p.getZ());
    grown = true;
  }

  void visit(StemImpl stem) {
    int l = Math.min(stem.stemlevel, 3);
    f[7 + l] += 1;
    for (Enumeration e = stem.segments.elements(); e.hasMoreElements();) {
      SegmentImpl s = (SegmentImpl) e.nextElement();
      f[3 + l] += s.length;
      point(s.transf.getT());
      point(s.transf.getT().add(s.transf.getZ().mul(s.length)));
    }
    if (stem.leaves != null) f[2] += stem.leaves.size();
    if (stem.substems != null)
      for (Enumeration e = stem.substems.elements(); e.hasMoreElements();) visit((StemImpl) e.nextElement());
    if (stem.clones != null)
      for (Enumeration e = stem.clones.elements(); e.hasMoreElements();) visit((StemImpl) e.nextElement());
  }

  static ArbaroFigures grow(String file, int seed) throws Exception {
    Params params = new Params();
    params.readFromXML(new FileInputStream(file));
    TreeGeneratorImpl g = new TreeGeneratorImpl(params);
    g.setSeed(seed);
    TreeImpl tree = (TreeImpl) g.makeTree(new Progress());
    ArbaroFigures t = new ArbaroFigures();
    for (Enumeration e = tree.trunks.elements(); e.hasMoreElements();) t.visit((StemImpl) e.nextElement());
    t.f[0] = t.maxZ;
    t.f[1] = 0.5 * ((t.maxX - t.minX) + (t.maxY - t.minY));
    return t;
  }

  public static void main(String[] args) throws Exception {
    Console.setOutputLevel(Console.REALLY_QUIET);
    int a = 0;
    boolean perSeed = args[a].equals("--per-seed");
    if (perSeed) ++a;
    int seeds = Integer.parseInt(args[a++]);
    StringBuilder head = new StringBuilder(perSeed ? "species,seed" : "species,seeds");
    for (String n : NAMES) head.append(",").append(n).append(perSeed ? "" : "," + n + "_sd");
    System.out.println(head);
    for (; a < args.length; ++a) {
      String name = new java.io.File(args[a]).getName().replace(".xml", "");
      List<double[]> rows = new ArrayList<double[]>();
      for (int seed = 1; seed <= seeds; ++seed) {
        ArbaroFigures t = grow(args[a], seed);
        if (!t.grown) continue;
        rows.add(t.f);
        if (perSeed) {
          StringBuilder r = new StringBuilder(name + "," + seed);
          for (double x : t.f) r.append(String.format(",%.6g", x));
          System.out.println(r);
        }
      }
      if (perSeed) continue;
      StringBuilder r = new StringBuilder(name + "," + rows.size());
      for (int i = 0; i < NAMES.length; ++i) {
        double m = 0, v = 0;
        for (double[] x : rows) m += x[i] / rows.size();
        for (double[] x : rows) v += (x[i] - m) * (x[i] - m) / Math.max(1, rows.size() - 1);
        r.append(String.format(",%.6g,%.4g", m, Math.sqrt(v)));
      }
      System.out.println(r);
    }
  }
}
