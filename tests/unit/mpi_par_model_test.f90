!> MPI test of the rank sub-model (dx_par_model) with the real hex8 kernels, run by
!> scripts/run_mpi_tests.sh serially and under mpirun -np 2/3/4: the taylor_simo deck
!> (ELFORM 1) and extreme_incompressible_elform2 (ELFORM 2),
!> perturbed coordinates and velocities, the lumped mass and two element passes (the
!> kernels with their material, bulk viscosity and hourglass forces) computed serially on every rank
!> and on the rank's sub-model with one exchange each; the rank's nodal mass and force must
!> equal the serial ones bit for bit at every node it holds.
program mpi_par_model_test
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_allreduce, PAR_MAX
   use dx_model, only: model_t, elem_block_t
   use dx_deck_model, only: read_deck
   use dx_explicit, only: init_state
   use dx_hex8, only: hex8_block
   use dx_element_types, only: block_result_t
   use dx_partition, only: partition_t, rank_part_t, partition_model, rank_part
   use dx_par_model, only: par_model_t, par_model_build, par_fill_slots, par_exchange_forces, &
                           par_exchange_mass, par_model_from_file, par_model_fill_state
   use dx_assert, only: check, assert_summary
   implicit none
   type(error_t), allocatable :: error
   integer :: np, me

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size(); me = par_rank()
   call run_deck('tests/regression/taylor_simo/deck.k', 'ELFORM 1')
   call run_deck('tests/regression/extreme_incompressible_elform2/deck.k', 'ELFORM 2')
   call par_finalize()
   if (me == 0) call assert_summary()

contains

   !> Mass and two element passes of one deck, serial against the rank's sub-model.
   subroutine run_deck(deck, label)
      character(*), intent(in) :: deck, label
      type(model_t) :: model
      type(partition_t) :: part
      type(rank_part_t) :: rp
      type(par_model_t) :: pm, pms(2)
      real(wp), allocatable :: x_start(:, :)
      type(elem_block_t), allocatable :: blocks0(:)
      character(:), allocatable :: lab
      integer :: way
      type(block_result_t) :: res
      real(wp), allocatable :: xl(:, :), vl(:, :), fl(:, :), ml(:), f(:, :)
      real(wp) :: dt_old, ro
      integer :: n, i, k, b, pass, gp(1), ge(0), nl
      integer(int64) :: st
      logical :: ok, ok_mass, ok_nonzero
      call read_deck(deck, model, error)
      if (allocated(error)) error stop 'cannot read the deck'
      gp = 1
      call partition_model(model, np, gp, ge, part, error)
      if (allocated(error)) error stop 'partition failed'
      call rank_part(model, part, me, rp, error)
      ! the sub-models first: their blocks copy the initial element state. pms(1): cut from
      ! the global model; pms(2): built from the rank file's sub-model (issue 22 stage 1)
      call par_model_build(model, rp, pms(1))
      call par_model_from_file(rp, pms(2))
      call par_model_fill_state(pms(2), model, rp)
      call init_state(model)
      st = 99_int64
      do n = 1, model%nn
         do i = 1, 3
            model%x(i, n) = model%x0(i, n)*(1.0_wp + 2.0e-3_wp*(rnd(st) - 0.5_wp))
            model%v(i, n) = model%v0(i, n) + 50.0_wp*(rnd(st) - 0.5_wp)
         end do
      end do
      dt_old = 1.0e-4_wp
      x_start = model%x
      blocks0 = model%blocks       ! the serial reference passes change the element state
      do way = 1, 2
      model%x = x_start
      model%blocks = blocks0
      pm = pms(way)
      lab = label//trim(merge(' (cut)      ', ' (from file)', way == 1))
      if (allocated(ml)) deallocate(ml, xl, vl, fl, f)
      nl = pm%nloc + pm%nslot
      ! lumped mass on the sub-model: init_state's loop (element-major), then the exchange
      allocate(ml(nl))
      ml = 0.0_wp
      do b = 1, size(pm%blocks)
         associate (blk => pm%blocks(b))
            ro = model%mats(model%parts(blk%ipart)%imat)%m%ro
            do i = 1, blk%nel
               do k = 1, 8
                  ml(blk%conn(k, i)) = ml(blk%conn(k, i)) + ro*blk%vol0(i)/8.0_wp
               end do
            end do
         end associate
      end do
      call par_exchange_mass(pm, ml)
      ok_mass = all(transfer(ml(1:pm%nloc), 1_int64, pm%nloc) == &
                    transfer(model%mass(pm%node_global), 1_int64, pm%nloc))
      call check_all(ok_mass, lab//': lumped mass on the rank = serial mass bit for bit')
      allocate(xl(3, nl), vl(3, nl), fl(3, nl), f(3, model%nn))
      do pass = 1, 2
         ! serial element pass (every rank, for the reference)
         f = 0.0_wp
         do b = 1, size(model%blocks)
            call hex8_block(model%blocks(b), model%mats(model%parts(model%blocks(b)%ipart)%imat)%m, &
                            model%parts(model%blocks(b)%ipart), model%x, model%v, dt_old, f, res)
         end do
         ! the rank's pass on its sub-model, then the one exchange
         xl(:, 1:pm%nloc) = model%x(:, pm%node_global)
         vl(:, 1:pm%nloc) = model%v(:, pm%node_global)
         call par_fill_slots(pm, xl)
         call par_fill_slots(pm, vl)
         fl = 0.0_wp
         do b = 1, size(pm%blocks)
            call hex8_block(pm%blocks(b), model%mats(model%parts(pm%blocks(b)%ipart)%imat)%m, &
                            model%parts(pm%blocks(b)%ipart), xl, vl, dt_old, fl, res)
         end do
         call par_exchange_forces(pm, fl)
         ok = all(transfer(fl(:, 1:pm%nloc), 1_int64, 3*pm%nloc) == &
                  transfer(f(:, pm%node_global), 1_int64, 3*pm%nloc))
         ok_nonzero = maxval(abs(f)) > 0.0_wp
         call check_all(ok .and. ok_nonzero, lab//': element pass '//achar(48 + pass)// &
                        ': nodal force on the rank = serial force bit for bit (nonzero forces)')
         ! move the nodes a little for the next pass (same on both sides)
         model%x = model%x + dt_old*model%v
      end do
      end do
   end subroutine run_deck

   subroutine check_all(cond, name)
      logical, intent(in) :: cond
      character(*), intent(in) :: name
      integer :: bad
      bad = merge(0, 1, cond)
      call par_allreduce(bad, PAR_MAX)
      if (me == 0) call check(bad == 0, name//' (np = '//achar(48 + np)//')')
   end subroutine check_all

   real(wp) function rnd(s)
      integer(int64), intent(inout) :: s
      s = modulo(16807_int64*s, 2147483647_int64)
      rnd = real(s, wp)/2147483647.0_wp
   end function rnd
end program mpi_par_model_test
