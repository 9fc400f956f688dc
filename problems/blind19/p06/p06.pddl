; blind19 p06: store a cube, a wafer and a bottle, one per spot, in any
; assignment the geometry allows. The spots: `nook`, under a board 10 cm
; over the table (the bottle is too tall; the wafer is too flat for a side
; grasp and the KUKA's palm cannot come down over it under the board);
; `pedestal`, a fixed drum r 3.2 cm (only the bottle, r 2.5 cm, fits its
; top: a cube's or the wafer's corners overhang); `tray`, open table.
; Only cube -> nook, wafer -> tray, bottle -> pedestal works.
; Expected (6 actions, any order): (pick cube cube-home) (place cube nook)
; (pick wafer wafer-home) (place wafer tray) (pick bottle bottle-home)
; (place bottle pedestal)
(define (problem p06)
  (:domain store-anywhere)
  (:objects cube wafer bottle - item
            nook pedestal tray - spot
            cube-home wafer-home bottle-home - home)
  (:init (at cube cube-home) (at wafer wafer-home) (at bottle bottle-home)
         (free nook) (free pedestal) (free tray) (handempty))
  (:goal (forall (?o - item) (exists (?s - spot) (at ?o ?s)))))
